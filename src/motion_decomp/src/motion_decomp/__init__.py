"""motion_decomp: executes the agents' move/turn actions on a mobile base (thesis §5.3, §6.3).

:mod:`motion_decomp.monitor` is the core without rospy (parsing, end detection, FIFO);
:mod:`motion_decomp.node` is the rospy node (import it only where rospy is available).
"""
