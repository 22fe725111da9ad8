"""vision_synth: robot(Name, Angle, Depth, Yaw) perceptions from a Kinect-like camera (thesis §6.2).

:mod:`vision_synth.detector` (masks, blobs, pairs), :mod:`vision_synth.geometry` (angle,
depth, yaw and their signs), :mod:`vision_synth.literals` (Jason syntax) and
:mod:`vision_synth.cloud` (PointCloud2/Image <-> numpy) are ROS-free (cloud needs only the
sensor_msgs message classes); :mod:`vision_synth.node` is the rospy node (import it only
where rospy is available).
"""
