"""A mend for rospy's registration, applied before ``rospy.init_node``.

rospy queues each publisher list it learns for a topic, from the answer to its own
``registerSubscriber`` and from the master's ``publisherUpdate`` calls, and its registration
thread connects only to the newest list queued for a topic, dropping the older ones. The two
come from different threads: when a publisher registers in the same moment as the
subscriber, the master's update naming it can be queued first and the stale answer (no
publishers) after it. The subscriber then never connects, and nothing tells it so.

rospy only ever adds connections from these lists (a connection to a publisher that is gone
ends on its own), so a list queued for a topic that still waits is merged with the waiting
one: every publisher either names is connected to."""
from rospy.impl.registration import RegManager


def merged_update(updates, topic, uris):
    """``updates`` (``[(topic, publisher URIs)]``) with ``uris`` queued for ``topic``: one
    entry for it, last, naming the publishers of any entry it had and of ``uris``."""
    waiting = [uri for name, listed in updates if name == topic for uri in listed]
    return [u for u in updates if u[0] != topic] + [(topic, list(dict.fromkeys(waiting + list(uris))))]


def _publisher_update(self, resolved_name, uris):
    with self.cond:
        self.updates = merged_update(self.updates, resolved_name, uris)
        self.cond.notify_all()


def mend_registration():
    """Make rospy's registration keep every publisher it is told of (idempotent)."""
    RegManager.publisher_update = _publisher_update
