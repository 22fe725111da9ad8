"""rason_wiring: a robot wired to Jason agents by configuration, without code.

Pure modules (no rospy, unit-tested without a master): :mod:`terms` (Jason text <-> values),
:mod:`fields` (message fields by path), :mod:`config` (``~actions`` checked into mappings),
:mod:`synth` (``~perceptions`` checked into syntheses, and the publication gate),
:mod:`ros_types` (types by name). :mod:`node` is the ``generic_decomposer`` node,
:mod:`synth_node` the ``generic_synthesizer`` node.
"""
