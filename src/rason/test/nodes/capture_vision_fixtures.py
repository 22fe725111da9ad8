#!/usr/bin/python3
"""Records simulator frames as vision_synth test fixtures (a test-data tool, not a test).

Start the simulator with the vision test world first, e.g.
  roslaunch rason sim.launch world:=$(rospack find rason)/test/worlds/vision.yaml \
      helper_x:=0 helper_y:=0 faulty_x:=2 faulty_y:=3 [brightness:=0.3]
then: capture_vision_fixtures.py OUT_DIR PREFIX
Each scene teleports the robots, waits for a fresh frame and writes OUT_DIR/PREFIX_<scene>
with the truth from the simulator's true poses.
"""
import math
import os
import sys

import numpy as np
import rason_rospy
import rospy
from sensor_msgs.msg import PointCloud2

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from sim_testing import CAMERA_FORWARD, SimRobot, camera_truth  # noqa: E402

# (name, helper pose, faulty pose (depth, angle deg, heading psi deg) or a world pose, robot in view)
SCENES = [
    ('centre_2m', (0.0, 0.0, 0.0), ('camera', 2.0, 0.0, 30.0), True),
    ('left_1m5', (0.0, 0.0, 0.0), ('camera', 1.5, -18.0, -40.0), True),
    ('right_3m_facing', (0.0, 0.0, 0.0), ('camera', 3.0, 18.0, 160.0), True),
    ('empty', (0.0, 0.0, 0.0), ('world', -2.5, 2.5, 0.0), False),
    # The box at (-1.0, 0.06) in worlds/vision.yaml hides the orange cylinder.
    ('occluded', (0.0, 0.0, math.pi), ('world', -2.0, 0.0, math.pi), False),
]


def faulty_world_pose(helper, spec):
    kind, a, b, c = spec
    if kind == 'world':
        return a, b, c
    depth, angle, psi = a, math.radians(b), math.radians(c)
    hx, hy, hyaw = helper
    forward, right = CAMERA_FORWARD + depth, depth * math.tan(angle)
    return (hx + forward * math.cos(hyaw) + right * math.sin(hyaw),
            hy + forward * math.sin(hyaw) - right * math.cos(hyaw), hyaw - psi)


def main(out_dir, prefix, scenes):
    sys.path.insert(0, os.path.join(HERE, '..', '..', '..', 'vision_synth', 'test'))
    import vision_fixtures  # the vision_synth tests' own loader/saver
    from vision_synth import cloud
    rason_rospy.init_node('capture_vision_fixtures')
    helper, faulty = SimRobot('helper'), SimRobot('faulty')
    for name, helper_pose, spec, in_view in SCENES:
        if scenes and name not in scenes:
            continue
        helper.teleport(*helper_pose, settle=0.0)
        faulty.teleport(*faulty_world_pose(helper_pose, spec), settle=0.3)
        msg = rospy.wait_for_message('/helper/camera/depth_registered/points', PointCloud2, timeout=10)
        xyz, rgb = cloud.cloud_to_arrays(msg)
        angle, depth, yaw = camera_truth(helper.pose(), faulty.pose())
        expected = {'name': 'faulty', 'angle': round(angle, 2), 'depth': round(depth, 3),
                    'yaw': round(yaw, 2)} if in_view else None
        meta = {'fx': 589.3666835307065, 'fy': 589.3666835307065, 'cx': 319.5, 'cy': 239.5,
                'expected': expected,
                'source': 'rason_sim, brightness %s, scene %s' % (
                    rospy.get_param('/rason_sim/brightness', 1.0), name)}
        vision_fixtures.save('%s_%s' % (prefix, name), np.ascontiguousarray(rgb), xyz, meta,
                             folder=out_dir)
        print('wrote %s_%s: %s' % (prefix, name, expected))


if __name__ == '__main__':
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3:])
