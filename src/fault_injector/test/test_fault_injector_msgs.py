"""Unit tests of the message helpers of fault_injector.node; imports rospy but needs no master."""
import math

import pytest
import rospy
from nav_msgs.msg import Odometry

from fault_injector import node


def _odom(seq, secs, x, frame='odom', child='base_link'):
    msg = Odometry()
    msg.header.seq = seq
    msg.header.stamp.secs = secs
    msg.header.frame_id = frame
    msg.child_frame_id = child
    msg.pose.pose.position.x = x
    msg.pose.pose.orientation.w = 1.0
    msg.twist.twist.linear.x = x / 10.0
    return msg


def test_odom_numbers_order():
    msg = _odom(1, 2, 3.0)
    msg.twist.twist.angular.z = 7.0
    numbers = node.odom_numbers(msg)
    assert len(numbers) == 13
    assert numbers[0] == 3.0 and numbers[6] == 1.0 and numbers[7] == 0.3 and numbers[12] == 7.0


def test_odom_numbers_sees_nan():
    msg = _odom(1, 2, float('nan'))
    assert any(math.isnan(v) for v in node.odom_numbers(msg))


def test_frozen_odometry_keeps_values_follows_stamp():
    frozen = _odom(1, 10, 1.0)
    incoming = _odom(5, 14, 9.0, frame='other', child='other_child')
    out = node.frozen_odometry(frozen, incoming)
    assert out.pose.pose.position.x == 1.0
    assert out.twist.twist.linear.x == 0.1
    assert out.header.frame_id == 'odom' and out.child_frame_id == 'base_link'
    assert out.header.stamp.secs == 14 and out.header.seq == 5
    # neither input is modified
    assert frozen.header.stamp.secs == 10 and incoming.pose.pose.position.x == 9.0


def test_frozen_odometry_same_message_unchanged():
    msg = _odom(1, 10, 1.0)
    assert node.frozen_odometry(msg, msg) is msg


class _ClosedTopic(object):
    def publish(self, msg):
        raise rospy.ROSException('publish() to a closed topic')


def test_publish_during_shutdown_drops_the_message_and_otherwise_raises(monkeypatch):
    monkeypatch.setattr(rospy.core, 'is_shutdown_requested', lambda: True)
    node._publish(_ClosedTopic(), Odometry())  # dropped quietly
    monkeypatch.setattr(rospy.core, 'is_shutdown_requested', lambda: False)
    with pytest.raises(rospy.ROSException):
        node._publish(_ClosedTopic(), Odometry())
