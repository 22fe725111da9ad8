"""ROS types by name at run time (``roslib.message``; no rospy): what
:func:`rason_wiring.config.parse` calls the resolver."""
import roslib.message


def _split(name):
    # 'move_base_msgs/MoveBaseAction' and 'move_base_msgs/MoveBase' both name the action MoveBase
    return name[:-len('Action')] if name.endswith('Action') else name


class Resolver(object):
    """Finds message, service and action classes; None for a type that does not exist."""

    @staticmethod
    def _find(get, name):
        if '/' not in name:
            return None
        try:
            return get(name)
        except (ValueError, ImportError, AttributeError):
            return None

    def message(self, name):
        return self._find(roslib.message.get_message_class, name)

    def service(self, name):
        return self._find(roslib.message.get_service_class, name)

    def action(self, name):
        return self.message(_split(name) + 'Action')

    def action_goal(self, name):
        return self.message(_split(name) + 'Goal')

    def action_result(self, name):
        return self.message(_split(name) + 'Result')

    def action_feedback(self, name):
        return self.message(_split(name) + 'Feedback')
