"""Who is connected to whom on the ROS graph, as rason_mas needs to know it (rospy plumbing)."""
import time

import rosgraph
import rospy


def publisher(msg):
    """The node that published msg (its connection's callerid), '' if unknown."""
    header = msg._connection_header
    return header.get('callerid', '') if header else ''


def linked(pub, node):
    """Whether publisher ``pub`` is connected to ``node`` now."""
    impl = pub.impl
    return impl is not None and impl.has_connection(node)


def linked_processes(pub):
    """Node names publisher ``pub`` is connected to (rospy keeps them as endpoint ids)."""
    impl = pub.impl
    return [] if impl is None else [c.endpoint_id for c in list(impl.connections)]


def event_publishers(sub):
    """Nodes whose link to subscriber ``sub`` is up (a decomposer that died has none)."""
    impl = sub.impl if sub is not None else None
    return [] if impl is None else [c.header.get('callerid', '') for c in list(impl.connections)
                                    if getattr(c, 'header', None)]


class Graph(object):
    """What the master lists, as seen by node ``caller_id``."""

    def __init__(self, caller_id):
        self._master = rosgraph.Master(caller_id)

    def registered(self, topic, publishers):
        """Nodes the master lists as publishers (or subscribers) of topic; None if unreachable."""
        try:
            pubs, subs, _ = self._master.getSystemState()
        except Exception as e:
            rospy.logwarn_throttle(10, 'cannot ask the master who uses %s: %s', topic, e)
            return None
        return sum(len(nodes) for t, nodes in (pubs if publishers else subs) if t == topic)

    def listed_subscribers(self, topic, pub):
        """Subscribers of topic the master lists; publisher ``pub``'s connections if it cannot be reached."""
        listed = self.registered(topic, publishers=False)
        return pub.get_num_connections() if listed is None else listed

    def wait_for_publishers(self, sub, timeout):
        """Wait (up to timeout s) until subscriber ``sub`` is connected to every publisher the master lists."""
        deadline = time.monotonic() + timeout
        while not rospy.is_shutdown():
            listed = self.registered(sub.resolved_name, publishers=True)
            if listed is None or sub.get_num_connections() >= listed or time.monotonic() > deadline:
                return
            time.sleep(0.02)
