"""lamp: a tiny std_srvs/SetBool service ``lamp`` standing for a device of the robot that only
a service switches (the patrol example calls it through generic_decomposer). It logs each
switch and answers success, or a failure (message ``already_on`` / ``already_off``) when the
lamp is already so."""
import rason_rospy
import rospy
from std_srvs.srv import SetBool, SetBoolResponse


class Lamp(object):

    def __init__(self):
        self.on = False

    def switch(self, on):
        """-> (success, message)."""
        if on == self.on:
            return False, 'already_on' if on else 'already_off'
        self.on = on
        return True, 'on' if on else 'off'


def main():
    rason_rospy.init_node('lamp')
    lamp = Lamp()

    def serve(request):
        success, message = lamp.switch(request.data)
        rospy.loginfo('lamp: %s%s', message, '' if success else ' (nothing switched)')
        return SetBoolResponse(success, message)

    rospy.Service('lamp', SetBool, serve)
    rospy.spin()
