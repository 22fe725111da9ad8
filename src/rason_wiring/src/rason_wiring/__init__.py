"""rason_wiring: a robot wired to Jason agents by configuration, without code.

Pure modules (no rospy, unit-tested without a master): :mod:`terms` (Jason text <-> values),
:mod:`fields` (message fields by path), :mod:`config` (``~actions`` checked into mappings),
:mod:`ros_types` (types by name). :mod:`node` is the ``generic_decomposer`` node.
"""
