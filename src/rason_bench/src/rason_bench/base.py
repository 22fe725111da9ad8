"""``bench_base``: a kinematic stand-in for a robot base, for the preemption benchmark.

Subscribes ``cmd_vel`` (geometry_msgs/Twist) and publishes ``odom`` (nav_msgs/Odometry)
at ``~rate`` Hz (50), integrating the last command (:func:`rason_bench.preempt.integrate`:
a unicycle, no inertia, no command timeout). Enough for motion_decomp to see its motion
progress; no physics.

~params: ``rate`` (float Hz, 50), ``frame_id`` (``odom``), ``child_frame_id`` (``base_footprint``).
"""
import threading
import time

import rason_rospy
import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

from rason_bench.preempt import integrate, yaw_quaternion


def main():
    rason_rospy.init_node('bench_base')
    rate = float(rospy.get_param('~rate', 50.0))
    frame_id = rospy.get_param('~frame_id', 'odom')
    child_frame_id = rospy.get_param('~child_frame_id', 'base_footprint')
    lock = threading.Lock()
    command = [0.0, 0.0]

    def on_cmd_vel(msg):
        with lock:
            command[:] = [msg.linear.x, msg.angular.z]

    pub = rospy.Publisher('odom', Odometry, queue_size=10, tcp_nodelay=True)
    rospy.Subscriber('cmd_vel', Twist, on_cmd_vel, queue_size=10, tcp_nodelay=True)
    pose = (0.0, 0.0, 0.0)
    period = 1.0 / rate
    last = next_time = time.monotonic()
    while not rospy.is_shutdown():
        now = time.monotonic()
        with lock:
            linear_x, angular_z = command
        pose = integrate(pose, linear_x, angular_z, now - last)
        last = now
        msg = Odometry()
        msg.header.stamp = rospy.Time.now()
        msg.header.frame_id = frame_id
        msg.child_frame_id = child_frame_id
        msg.pose.pose.position.x, msg.pose.pose.position.y = pose[0], pose[1]
        q = msg.pose.pose.orientation
        q.x, q.y, q.z, q.w = yaw_quaternion(pose[2])
        msg.twist.twist.linear.x, msg.twist.twist.angular.z = linear_x, angular_z
        pub.publish(msg)
        next_time += period
        delay = next_time - time.monotonic()
        if delay > 0:
            time.sleep(delay)
        else:
            next_time = time.monotonic()  # late: no burst to catch up
