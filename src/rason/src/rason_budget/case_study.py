"""One case-study run (faulty_helper.launch ``budget:=true``) with each robot's nodes in a CPU
group of its own, measured: what the case_study_budget rostest and the bench's budget part run.

The run is a campaign run (rason_campaign.runner: its own master, a bag, the diagnosis read
from it) at real-time factor 1 with the lockstep off; the simulator, master, rosout and
recorder run outside every group. rason_mas gets a robot's JVM options (rason_bridge.jvm's,
then the shell's RASON_JVM_OPTIONS), not the campaign's options for short-lived JVMs."""
import json
import os

from rason_budget import cgroups
from rason_budget.meter import Meter
from rason_campaign import bagread, cli, plan, runner

ROBOTS = ('faulty', 'helper')
SEED = 7


def run(fault, cores, out_dir, seed=SEED, interval=0.5, timeout=240, base_port=11911):
    """(the campaign's result dict, the meter's summary) of one run with each robot held to
    ``cores`` (None: no quota, measured only); the bag, log and ``budget.json`` in out_dir."""
    (spec,) = plan.make_plan([fault], 1, seed, rate=1.0, jitter=False)
    spec.args.update(lockstep='false', budget='true')
    os.makedirs(out_dir, exist_ok=True)
    with cgroups.Budget({robot: cores for robot in ROBOTS}) as budget:
        launch = []
        meter = Meter(budget, interval=interval, root_pid=lambda: launch[0].pid if launch else None)
        env = dict(budget.env, RASON_JVM_OPTIONS=os.environ.get('RASON_JVM_OPTIONS', ''))
        with meter:
            record = runner.run(spec, out_dir, timeout=timeout, base_port=base_port, env=env,
                                on_start=launch.append)
    summary = meter.summary()
    with open(os.path.join(out_dir, 'budget.json'), 'w') as f:
        json.dump(summary, f, indent=1, sort_keys=True)
    return cli.analyze(spec, record, bagread.read_events), summary
