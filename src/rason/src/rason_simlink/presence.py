"""Presence bookkeeping: what the world side mirrors of the robot master's graph.

The robot side reports which on-demand topics have a subscriber on the robot's master and
which acknowledgement topics have a publisher there. The world side subscribes to a camera
topic only while it is wanted (the simulator renders only for subscribers) and advertises an
acknowledgement topic only while a publisher feeds it (the simulator's lockstep waits on an
acknowledgement topic as long as it has a publisher). A dropped link wants nothing.
"""
from . import topics


def presence_report(subscribed, publishing):
    """The PRESENCE record's value from two iterables of topic names."""
    return {'subscribed': sorted(subscribed), 'publishing': sorted(publishing)}


class RobotPresence:
    """The robot side's view: what to report, and whether it changed since last sent."""

    def __init__(self):
        self._sent = None

    def update(self, subscriber_counts, publisher_counts):
        """The report to send if it differs from the last one sent, else None.

        subscriber_counts: {on-demand topic: subscribers on the robot master};
        publisher_counts: {ack topic: publishers on the robot master}.
        """
        report = presence_report([n for n, c in subscriber_counts.items() if c > 0],
                                 [n for n, c in publisher_counts.items() if c > 0])
        if report == self._sent:
            return None
        self._sent = report
        return report

    def forget(self):
        """The link was dropped: the next update reports in full."""
        self._sent = None


class WorldPresence:
    """The world side's mirror: the changes to make as reports come and links go."""

    def __init__(self):
        self.subscribed = set()    # on-demand topics the world side subscribes to
        self.advertised = set()    # ack topics the world side advertises

    def apply(self, report):
        """(subscribe, unsubscribe, advertise, unadvertise): sets of topic names.

        Names that are not on-demand / ack topics are ignored (returned in unknown).
        """
        wanted_subs = set(report.get('subscribed', ()))
        wanted_pubs = set(report.get('publishing', ()))
        on_demand = {t.name for t in topics.TOPICS if t.on_demand}
        acks = {t.name for t in topics.TOPICS if t.ack}
        unknown = (wanted_subs - on_demand) | (wanted_pubs - acks)
        return self._move(wanted_subs & on_demand, wanted_pubs & acks) + (unknown,)

    def link_lost(self):
        """(subscribe, unsubscribe, advertise, unadvertise) when the link is gone."""
        return self._move(set(), set())

    def _move(self, subs, pubs):
        changes = (subs - self.subscribed, self.subscribed - subs,
                   pubs - self.advertised, self.advertised - pubs)
        self.subscribed, self.advertised = subs, pubs
        return changes
