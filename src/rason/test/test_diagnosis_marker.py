"""rviz's diagnosis marker (no ROS master) and the rviz config of the simulated world."""
import os

import yaml
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus, KeyValue
from geometry_msgs.msg import Point, Pose
from visualization_msgs.msg import Marker

from rason_tools.diagnosis_marker import HEIGHT, diagnosis_of, marker

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def status(name, level, **values):
    return DiagnosticStatus(name=name, level=level, message='m',
                            values=[KeyValue(k, v) for k, v in values.items()])


def test_diagnoses_by_agent_from_rason_diagnosis_only():
    array = DiagnosticArray(status=[
        status('rason/diagnosis', 1, agent='faulty', component='left_actuator'),
        status('rason/mission', 0, agent='faulty', completed='true'),
        status('rason/diagnosis', 0, component='none'),  # no agent: cannot be placed
        status('other', 2, agent='helper')])
    assert diagnosis_of(array) == {'faulty': (1, 'left_actuator')}


def test_marker_text_colour_and_place():
    pose = Pose(position=Point(1.0, -2.0, 0.0))
    m = marker(3, 'faulty', 2, 'both_actuators', pose, frame='world')
    assert (m.type, m.id, m.text, m.header.frame_id) == (Marker.TEXT_VIEW_FACING, 3, 'faulty: both_actuators', 'world')
    assert (m.pose.position.x, m.pose.position.y, m.pose.position.z) == (1.0, -2.0, HEIGHT)
    assert (m.color.r, m.color.g, m.color.a) == (0.9, 0.1, 1.0)
    assert m.scale.z > 0


def test_rviz_config_shows_what_the_simulation_publishes():
    with open(os.path.join(HERE, 'rviz', 'sim.rviz')) as f:
        config = yaml.safe_load(f)
    manager = config['Visualization Manager']
    assert manager['Global Options']['Fixed Frame'] == 'world'  # the frame of the true poses
    topics = {d.get('Topic') or d.get('Marker Topic') or d.get('Image Topic') for d in manager['Displays']}
    assert {'/faulty/true_pose', '/helper/true_pose', '/diagnosis_markers',
            '/helper/camera/rgb/image_raw'} <= topics
