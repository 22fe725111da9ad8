"""Rason bridge: real Jason agents on ROS topics.

Public API: :func:`start_jvm`, :class:`RasonMasNode` (import it from
``rason_bridge.mas_node``; it needs rospy), the pure helpers in
:mod:`rason_bridge.action_sender`, :mod:`rason_bridge.message_sender`, the ~param schema
:mod:`rason_bridge.params` and :mod:`rason_bridge.fleet_auth`, and the key tool :mod:`rason_bridge.fleet_key`.
"""
from rason_bridge.jvm import JvmError, jason_lib_classpath, start_jvm  # noqa: F401
