"""What every Rason rospy node does to start: :func:`init_node`."""
import rospy

from rason_rospy.quick_start import name_logging_config, poll_registration_every
from rason_rospy.registration import mend_registration


def init_node(name, **kwargs):
    """``rospy.init_node(name, **kwargs)``, with rospy's registration mended first, and sooner
    registered and logging (:mod:`rason_rospy.quick_start`)."""
    mend_registration()
    poll_registration_every()
    name_logging_config()
    rospy.init_node(name, **kwargs)
