"""What every Rason rospy node does to start: :func:`init_node`."""
import rospy

from rason_rospy.registration import mend_registration


def init_node(name, **kwargs):
    """``rospy.init_node(name, **kwargs)``, with rospy's registration mended first."""
    mend_registration()
    rospy.init_node(name, **kwargs)
