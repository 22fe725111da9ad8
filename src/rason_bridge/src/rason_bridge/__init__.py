"""Rason bridge: real Jason agents on ROS topics.

Public API: :func:`start_jvm`, :class:`RasonMasNode` (import it from
``rason_bridge.mas_node``; it needs rospy), and the pure helpers in
:mod:`rason_bridge.outbox` and :mod:`rason_bridge.peers`.
"""
from rason_bridge.jvm import JvmError, jason_lib_classpath, start_jvm  # noqa: F401
