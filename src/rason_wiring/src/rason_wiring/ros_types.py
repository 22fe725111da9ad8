"""ROS types by name at run time, imported from their packages' generated Python modules (no
rospy): what :func:`rason_wiring.config.parse` calls the resolver.

``roslib.message.get_message_class`` is not used: on a name it cannot find it parses the
package's manifest, and rospkg then prints "the rosdep view is empty: call 'sudo rosdep init'",
advice that has nothing to do with a misspelt type and comes before the entry's own error."""
import importlib


def _split(name):
    # 'move_base_msgs/MoveBaseAction' and 'move_base_msgs/MoveBase' both name the action MoveBase
    return name[:-len('Action')] if name.endswith('Action') else name


def find_class(kind, name):
    """The class of ``PACKAGE/Type`` from ``PACKAGE.<kind>`` (``msg`` or ``srv``), or None."""
    package, _, base = name.partition('/')
    if not package.isidentifier() or not base.isidentifier():
        return None
    try:
        module = importlib.import_module('%s.%s' % (package, kind))
    except ImportError:
        return None
    found = getattr(module, base, None)
    return found if isinstance(found, type) and getattr(found, '_type', None) == name else None


class Resolver(object):
    """Finds message, service and action classes; None for a type that does not exist."""

    def message(self, name):
        return find_class('msg', name)

    def service(self, name):
        return find_class('srv', name)

    def action(self, name):
        return self.message(_split(name) + 'Action')

    def action_goal(self, name):
        return self.message(_split(name) + 'Goal')

    def action_result(self, name):
        return self.message(_split(name) + 'Result')

    def action_feedback(self, name):
        return self.message(_split(name) + 'Feedback')
