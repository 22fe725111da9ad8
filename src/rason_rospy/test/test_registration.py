"""rason_rospy's mend of rospy's registration: a subscriber told of a publisher by the master
while the stale answer to its own registration is still on its way connects to it all the
same. Runs rospy's own RegManager thread, with no master."""
import threading

import pytest
import rospy.impl.registration as registration
from rospy.impl.registration import RegManager

from rason_rospy.registration import mend_registration, merged_update

PUB = 'http://host:4100/'
OTHER = 'http://host:4200/'


def test_a_list_queued_for_a_waiting_topic_keeps_the_publishers_of_both():
    updates = [('/odom', [PUB]), ('/scan', [OTHER])]
    assert merged_update(updates, '/odom', []) == [('/scan', [OTHER]), ('/odom', [PUB])]
    assert merged_update(updates, '/odom', [OTHER, PUB]) == [('/scan', [OTHER]), ('/odom', [PUB, OTHER])]
    assert merged_update([], '/odom', [PUB]) == [('/odom', [PUB])]


class _TopicManager(object):
    def check_all(self):
        pass


class _Handler(object):
    """A node API handler that records the connections asked of it."""

    def __init__(self):
        self.done = False
        self.connected = []
        self.cond = threading.Condition()

    def _connect_topic(self, topic, uri):
        with self.cond:
            self.connected.append((topic, uri))
            self.cond.notify_all()
        return 1, 'connected', 1


@pytest.fixture
def topic_manager():
    saved = registration.get_topic_manager()
    registration.set_topic_manager(_TopicManager())
    yield
    registration.set_topic_manager(saved)


def test_the_masters_update_queued_before_the_stale_answer_still_connects(topic_manager):
    mend_registration()
    handler = _Handler()
    manager = RegManager(handler)
    # the order of the race: the master's publisherUpdate (naming the publisher) is queued
    # first, then registerSubscriber's answer from before the publisher registered
    manager.publisher_update('/r4/odom_commanded', [PUB])
    manager.publisher_update('/r4/odom_commanded', [])
    thread = threading.Thread(target=manager.run, daemon=True)
    thread.start()
    try:
        with handler.cond:
            assert handler.cond.wait_for(lambda: handler.connected, timeout=10.0), 'never connected'
            assert handler.connected == [('/r4/odom_commanded', PUB)]
    finally:
        handler.done = True
        with manager.cond:
            manager.cond.notify_all()
        thread.join(timeout=10.0)
    assert not thread.is_alive()


def test_mending_twice_is_mending_once():
    mend_registration()
    mended = RegManager.publisher_update
    mend_registration()
    assert RegManager.publisher_update is mended
