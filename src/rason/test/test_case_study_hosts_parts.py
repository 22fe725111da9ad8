"""The parts of rason_hosts.case_study that need no root: reading what the agents print, the
true poses from rostopic's CSV, the mission judged from them, the transcript's waits."""
import math
import subprocess
import sys
import threading

import pytest

from rason_hosts import HostsError
from rason_hosts.case_study import DIAGNOSIS, MISSION, SEARCH, Transcript, judge_mission, true_poses

HEADER = ('%time,field.header.seq,field.header.stamp,field.header.frame_id,field.pose.position.x,'
          'field.pose.position.y,field.pose.position.z,field.pose.orientation.x,'
          'field.pose.orientation.y,field.pose.orientation.z,field.pose.orientation.w')


def _row(x, y, yaw):
    return '1,2,3,world,%r,%r,0.0,0.0,0.0,%r,%r' % (x, y, math.sin(yaw / 2), math.cos(yaw / 2))


def test_the_agents_lines_are_read_as_rason_mas_prints_them():
    line = '[INFO] [1764198051.395]: [faulty] Diagnosis: both_actuators (no progress measured, and seen in the same place)'
    assert DIAGNOSIS.search(line).groups() == ('both_actuators', 'no progress measured, and seen in the same place')
    assert MISSION.search('[faulty] Mission completed: true by [faulty] (recovery compensate)').groups() \
        == ('true', 'faulty', 'compensate')
    assert MISSION.search('[faulty] Mission completed: false by [] (recovery delegate)').groups() \
        == ('false', '', 'delegate')
    assert SEARCH.search('[helper] Finding faulty turning 10 degrees, turned 0 so far. Threshold is 7')
    assert SEARCH.search('[helper] Found faulty')
    assert not DIAGNOSIS.search('[helper] Diagnosis: none (x)')   # only Faulty diagnoses


def test_true_poses_come_from_the_csv_columns_and_skip_what_is_not_a_row():
    lines = [(0.0, 'WARNING: no messages yet'), (1.0, HEADER), (2.0, _row(1.0, -0.5, math.pi / 2)),
             (3.0, '1,2,broken')]
    [(wall, x, y, yaw)] = true_poses(lines)
    assert (wall, x, y) == (2.0, 1.0, -0.5) and yaw == pytest.approx(math.pi / 2)


def test_the_mission_is_judged_from_the_start_pose_one_metre_ahead():
    start = (0.0, -1.0, -0.75, -math.pi / 2)
    at_goal = (1.0, -1.0, -1.75, -math.pi / 2)
    back = (2.0, -1.02, -0.76, math.pi / 2)
    closest, home = judge_mission({'faulty': [start, at_goal, back]})
    assert closest == pytest.approx(0.0, abs=1e-9)
    assert home == pytest.approx(math.hypot(0.02, 0.01))
    assert judge_mission({'faulty': []}) == (None, None)
    closest, _ = judge_mission({'faulty': [start, (1.0, -1.0, -1.25, 0.0)]})
    assert closest == pytest.approx(0.5)


def test_a_delegated_mission_is_judged_by_the_robot_that_completed_it():
    start = (0.0, -1.0, -0.75, -math.pi / 2)
    helper_at_goal = (5.0, -0.98, -1.75, 0.0)
    poses = {'faulty': [start, (9.0, -1.0, -0.75, -math.pi / 2)],
             'helper': [(0.0, -1.0, 0.75, 0.0), helper_at_goal]}
    closest, back = judge_mission(poses, ['helper'])
    assert closest == pytest.approx(0.02) and back is None
    closest, back = judge_mission(poses, ['faulty'])
    assert closest == pytest.approx(1.0) and back == pytest.approx(0.0)
    assert judge_mission(poses, ['helper', 'faulty'])[0] == pytest.approx(0.02)
    assert judge_mission({'helper': poses['helper']}, ['helper']) == (None, None)   # no start: no goal


def test_the_transcript_waits_for_a_line_and_says_what_it_missed():
    echoed = []
    transcript = Transcript(echo=lambda source, text: echoed.append((source, text)))
    proc = subprocess.Popen([sys.executable, '-c', 'print("one"); print("[faulty] Diagnosis: none (x)")'],
                            stdout=subprocess.PIPE)
    transcript.follow('p', proc)
    line = transcript.wait(DIAGNOSIS, 10, 'the diagnosis')
    assert line[1:] == ('p', '[faulty] Diagnosis: none (x)')
    proc.wait()
    assert transcript.first(DIAGNOSIS, since=line[0] + 1) is None
    with pytest.raises(HostsError, match='waited 0.2 s for the mission in vain'):
        transcript.wait(MISSION, 0.2, 'the mission')
    done = threading.Event()
    threading.Thread(target=lambda: (transcript.wait(DIAGNOSIS, 5, 'x'), done.set())).start()
    assert done.wait(5)
    assert ('p', 'one') in echoed
