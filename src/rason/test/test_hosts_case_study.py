"""The case study with each robot on a host of its own (issue 31): needs root (CI runs as root)
and the built workspace, skipped otherwise.

Faulty and Helper each run their own ROS master and rason_mas in a network namespace, talk
only over MQTT through a broker on a third host, and share one simulated world (a fourth
host) through the sim link's Unix sockets; rason_hosts.case_study plays it. Three runs, one a
test (each about a minute):

  - 20 % loss each way on each robot's link and 100 ms added each way: the diagnosis of
    both_actuators is right;
  - the same link, the fault-tolerance mission with left_actuator: the mission is completed,
    judged from Faulty's true poses on the world's master;
  - Helper's link cut for 5 s once its search began: both agents say the other is out of
    reach, the dialogue resumes after the heal, the diagnosis is right or `undiagnosed` with
    a reason, and no robot moves after the run ended.
"""
import math
import re
import time

import pytest

from rason_hosts import Hosts
from rason_hosts.case_study import HOST_NAMES, CaseStudyOnHosts

from hosts_agents import NEEDS_HOSTS_AND_WORKSPACE

pytestmark = NEEDS_HOSTS_AND_WORKSPACE

LOSS, DELAY_MS, PARTITION = 20, 100, 5.0
TOLERANCE = 0.15        # m: the fault-tolerance rostests' judge
STILL = 0.002           # m and rad a robot at rest may seem to move (the simulator's contacts)


def _play(tmp_path, after=None, **scenario):
    """The outcome of one run; after(run), if given, is called while the hosts still run."""
    folder = str(tmp_path)
    with Hosts(HOST_NAMES) as hosts:
        run = CaseStudyOnHosts(hosts, folder, **scenario)
        try:
            outcome = run.play()
            if after:
                after(run)
        finally:
            print('\nlogs in %s; phases (s from start): %s' % (folder, ', '.join(
                '%s %.1f' % (k, v - run.marks['start']) for k, v in
                sorted(run.marks.items(), key=lambda kv: kv[1]))))
    return outcome


def _stands_still(run, robot, start, seconds=1.0):
    """Whether robot's true pose stayed put (within STILL) from wall time start for seconds."""
    deadline = start + seconds + 10.0
    while True:
        poses = run.true_poses(robot)
        if poses and poses[-1][0] >= start + seconds:
            break
        assert time.time() < deadline, 'no true pose of %s after the run' % robot
        time.sleep(0.1)
    window = [p for p in poses if start <= p[0] <= start + seconds]
    assert len(window) > 10, 'too few true poses of %s after the run: %d' % (robot, len(window))
    moved = max(math.hypot(p[1] - window[0][1], p[2] - window[0][2]) for p in window)
    turned = max(abs(p[3] - window[0][3]) for p in window)
    return moved < STILL and turned < STILL


def test_both_actuators_diagnosed_across_hosts_on_a_lossy_slow_link(tmp_path):
    outcome = _play(tmp_path, fault='both_actuators', loss=LOSS, delay_ms=DELAY_MS)
    assert outcome.diagnosis[0] == 'both_actuators', outcome.transcript.tail()


def test_left_actuator_mission_completed_across_hosts_on_a_lossy_slow_link(tmp_path):
    outcome = _play(tmp_path, fault='left_actuator', recovery=True, loss=LOSS, delay_ms=DELAY_MS)
    assert outcome.diagnosis[0] == 'left_actuator', outcome.transcript.tail()
    assert outcome.mission == ('true', 'faulty', 'compensate'), outcome.transcript.tail()
    closest, back = outcome.mission_judged()
    assert closest <= TOLERANCE, 'Faulty came no closer than %.3f m to its goal' % closest
    assert back <= TOLERANCE, 'Faulty ended %.3f m from its start' % back


def test_partition_during_the_search_is_noticed_and_the_dialogue_resumes(tmp_path):
    still = {}

    def after(run):
        # no motion outlives its goal: from 2 s after the diagnosis, both robots stand still
        start = run.marks['diagnosis'] + 2.0
        for robot in ('faulty', 'helper'):
            still[robot] = _stands_still(run, robot, start)

    outcome = _play(tmp_path, after=after, fault='both_actuators', partition=PARTITION)
    lines, marks = outcome.transcript, outcome.marks
    cut, healed = marks['cut'], marks['cut'] + PARTITION
    timings = []
    for robot, other in (('helper', 'faulty'), ('faulty', 'helper')):
        noticed = lines.first(re.compile(r'\[%s\] %s is out of reach' % (robot, other)), since=cut)
        assert noticed, '%s never said %s was out of reach:\n%s' % (robot, other, lines.tail(60))
        assert noticed[0] < healed + 3, '%s noticed only %.1f s after the cut' % (robot, noticed[0] - cut)
        back = lines.first(re.compile(r'\[%s\] %s is back in reach' % (robot, other)), since=cut)
        timings.append('%s noticed the cut in %.1f s%s' % (robot, noticed[0] - cut, '' if not back else
                                                         ', saw %s back %.1f s after the heal' % (other, back[0] - healed)))
    # the dialogue resumes: a step of it after the heal
    resumed = lines.first(re.compile(r'\[(faulty|helper)\] (helper found me|I\'m ready|Trying to move'
                                     r'|reporting to|.*requesting some feedback|fault in|Diagnosis)'),
                          since=healed)
    assert resumed, 'no step of the dialogue after the heal:\n%s' % lines.tail(60)
    print('\npartition of %.0f s: %s; the dialogue resumed %.1f s after the heal (%s)'
          % (PARTITION, '; '.join(timings), resumed[0] - healed, resumed[2].split('] ', 1)[-1]))
    component, evidence = outcome.diagnosis
    assert component in ('both_actuators', 'undiagnosed'), outcome.diagnosis
    assert evidence, 'a diagnosis without its reason'
    assert still == {'faulty': True, 'helper': True}, 'a robot still moving after the run: %s' % still
