"""The budget part (``--only budget``, issue 35): what each robot of the case study needs.
faulty_helper.launch at real-time factor 1, lockstep off, each robot's nodes in a CPU group
of its own (rason_budget.case_study): once without a quota (what a robot takes) and once held
to QUOTA_CORES (whether the diagnosis is still right, and how often the quota bit)."""
import shutil
import tempfile

from rason_budget import case_study

QUOTA_CORES = 0.5
FAULTS, FAULTS_QUICK = ('both_actuators', 'left_actuator'), ('both_actuators',)


def measure(quick, log):
    """{'quota_cores', 'runs': [one dict per (fault, quota)]}; bags and logs are not kept."""
    runs = []
    tmp = tempfile.mkdtemp(prefix='rason_bench_budget_')
    try:
        for fault in FAULTS_QUICK if quick else FAULTS:
            for cores in (None, QUOTA_CORES):
                label = 'no quota' if cores is None else '%g core' % cores
                result, summary = case_study.run(fault, cores, '%s/%s_%s' % (tmp, fault, label.replace(' ', '_')))
                run = {'fault': fault, 'quota_cores': cores, 'outcome': result['outcome'],
                       'component': result['component'], 'reason': result['reason'], 'wall_s': result['wall'],
                       'steps_s': result['steps'], 'interval_s': summary['interval_s'],
                       'robots': summary['robots'], 'outside': summary.get('outside')}
                runs.append(run)
                log('  %s, %s: %s (%s), %.0f s; %s' % (fault, label, run['outcome'], run['component'], run['wall_s'] or 0,
                                                      '; '.join('%s CPU mean %.2f p95 %.2f core, RSS %.0f MB' % (
                                                          robot, r['cpu_mean_cores'], r['cpu_p95_cores'],
                                                          r['rss_total_peak_mb'])
                                                                for robot, r in sorted(run['robots'].items()))))
    finally:
        shutil.rmtree(tmp, True)
    return {'quota_cores': QUOTA_CORES, 'runs': runs}
