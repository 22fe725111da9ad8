"""Rason bridge: real Jason agents on ROS topics.

Public API: :func:`start_jvm`, :class:`RasonMasNode` (import it from
``rason_bridge.mas_node``; it needs rospy), the pure helpers in
:mod:`rason_bridge.outbox`, :mod:`rason_bridge.peers`, :mod:`rason_bridge.limits` and
:mod:`rason_bridge.fleet_auth`, and the key tool :mod:`rason_bridge.fleet_key`.
"""
from rason_bridge.jvm import JvmError, jason_lib_classpath, start_jvm  # noqa: F401
