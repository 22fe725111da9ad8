"""rason_wiring.type_check: an entry whose topic is published with another type is warned about,
with both types named, again only after a while or when the published type changes; and
rason_wiring.ros_types finds types without rospkg's rosdep advice. No ROS master."""
import os
import subprocess
import sys

from rason_wiring.type_check import TypeCheck

BATTERY = ('battery', '/faulty/battery', 'std_msgs/Float32')


def test_a_topic_published_with_another_type_is_warned_about_naming_both_types():
    check = TypeCheck([BATTERY, ('odometry', '/faulty/odom', 'nav_msgs/Odometry')])
    lines = check.warnings({'/faulty/battery': 'sensor_msgs/BatteryState', '/faulty/odom': 'nav_msgs/Odometry'}, 0.0)
    assert lines == ['battery: /faulty/battery is published as sensor_msgs/BatteryState, but the entry reads it as '
                     'std_msgs/Float32: it perceives nothing from it until the entry\'s type is sensor_msgs/BatteryState']


def test_a_matching_or_unpublished_topic_is_not_warned_about():
    check = TypeCheck([BATTERY])
    assert check.warnings({}, 0.0) == []
    assert check.warnings({'/faulty/battery': 'std_msgs/Float32'}, 1.0) == []
    assert check.warnings({'/other': 'sensor_msgs/BatteryState'}, 2.0) == []


def test_a_mismatch_that_goes_on_is_warned_about_again_only_after_the_repeat_time():
    check = TypeCheck([BATTERY], repeat=60.0)
    wrong = {'/faulty/battery': 'sensor_msgs/BatteryState'}
    assert len(check.warnings(wrong, 0.0)) == 1
    assert check.warnings(wrong, 30.0) == []
    assert len(check.warnings(wrong, 60.0)) == 1
    assert check.warnings({'/faulty/battery': 'std_msgs/Float32'}, 61.0) == []   # fixed ...
    assert len(check.warnings(wrong, 62.0)) == 1                                    # ... and broken again
    assert 'as std_msgs/String' in check.warnings({'/faulty/battery': 'std_msgs/String'}, 63.0)[0]


def test_an_unknown_type_is_none_without_rosdep_advice():
    # in a process of its own: rospkg prints its advice once a process
    code = ('from rason_wiring.ros_types import Resolver; r = Resolver(); '
            'print(r.message("std_msgs/Nope"), r.message("nope_msgs/Nope"), r.message("std_msgs/Float32")._type, '
            'r.service("std_srvs/Nope"), r.action("move_base_msgs/MoveBaseAction")._type)')
    done = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True, timeout=60,
                          env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ['None', 'None', 'std_msgs/Float32', 'None', 'move_base_msgs/MoveBaseAction']
    assert 'rosdep' not in done.stderr
