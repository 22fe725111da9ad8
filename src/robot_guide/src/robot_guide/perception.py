"""The ``located(Name, X, Y, Yaw)`` perception. No ROS.

X and Y in metres with 3 decimals, Yaw in radians with 3 decimals, COUNTER-clockwise from
the odometry frame's x axis (REP 103; unlike vision_synth's clockwise degrees), all in the
seeing robot's odometry frame, e.g. ``located(faulty,1.502,-0.031,3.136)``. Numbers are
written as vision_synth writes them (no ``-0``, no exponent, trailing zeros dropped).
"""
from vision_synth.literals import format_number, is_atom

DECIMALS = 3


def located_literal(located):
    """``located(Name,X,Y,Yaw)`` of a :class:`robot_guide.locate.Located`.

    :raises ValueError: a name that is not a Jason atom, a value that is not finite
    """
    if not is_atom(located.name):
        raise ValueError('robot name %r is not a Jason atom' % (located.name,))
    return 'located(%s,%s,%s,%s)' % (located.name, format_number(located.x, DECIMALS),
                                     format_number(located.y, DECIMALS),
                                     format_number(located.yaw, DECIMALS))
