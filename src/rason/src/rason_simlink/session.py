"""The sim link's protocol over one Connection, for either side.

Each side opens with HELLO (protocol, side, robot) and refuses a peer of the same side, of
another robot or of another protocol with a REFUSE saying why. A channel is announced
(TOPIC: name, type, md5) before its first message; the receiver checks it against its own
table and message definitions and drops, with a rate-limited error, the data of a channel
it refused.
"""
import threading

from . import framing, topics
from .reporting import RateLimited


class Session:

    def __init__(self, side, robot, connection, local_md5, publish, on_presence=None,
                 log_error=print, log_info=print, limiter=None, on_ready=None):
        """publish(topic, payload) puts a received message on this side's master;
        on_presence(report) (world side) applies the robot side's presence report;
        on_ready(session) is called once the peer's HELLO was accepted."""
        self._on_ready = on_ready
        self.side, self.robot = side, robot
        self.peer_ready = False
        self._conn = connection
        self._local_md5 = local_md5
        self._publish = publish
        self._on_presence = on_presence
        self._log_error, self._log_info = log_error, log_info
        self._limiter = limiter or RateLimited()
        self._out_channels = {}    # topic name -> channel
        self._in_channels = {}     # channel -> topic name, or None when refused
        self._refusals = {}        # channel -> reason
        self._send_lock = threading.Lock()   # callbacks of several topics send at once

    @property
    def closed(self):
        return self._conn.closed

    def close(self, reason):
        self._conn.close(reason)

    def start(self):
        self._conn.send_json(framing.HELLO, {'protocol': framing.PROTOCOL, 'side': self.side,
                                             'robot': self.robot})

    def send(self, topic_name, payload):
        """Relays one serialized message; False if the link dropped it."""
        with self._send_lock:
            channel = self._out_channels.get(topic_name)
            if channel is None:
                channel = len(self._out_channels)
                topic = topics.BY_NAME[topic_name]
                self._conn.send_json(framing.TOPIC, {'channel': channel, 'topic': topic_name,
                                                     'type': topic.type,
                                                     'md5': self._local_md5(topic.type)})
                self._out_channels[topic_name] = channel
            return self._conn.send_data(channel, payload)

    def send_presence(self, report):
        self._conn.send_json(framing.PRESENCE, report)

    def handle(self, kind, body):
        if kind == framing.DATA:
            self._on_data(*framing.decode_data(body))
            return
        value = framing.decode_json(body)
        if kind == framing.HELLO:
            self._on_hello(value)
        elif kind == framing.REFUSE:
            self._limiter.report('refused', self._log_error,
                                 'sim link %s: the %s side refused the link: %s'
                                 % (self.robot, self._peer_side(), value.get('reason')))
            self._conn.close('refused by the peer')
        elif kind == framing.TOPIC:
            self._on_topic(value)
        elif kind == framing.PRESENCE:
            if self.side != 'world' or self._on_presence is None:
                self._refuse('a presence report goes from the robot side to the world side')
            elif not self.peer_ready:
                self._refuse('a presence report before the HELLO')
            else:
                self._on_presence(value)

    def _peer_side(self):
        return 'robot' if self.side == 'world' else 'world'

    def _on_hello(self, hello):
        if hello.get('protocol') != framing.PROTOCOL:
            self._refuse('protocol %r, this side speaks %d' % (hello.get('protocol'),
                                                               framing.PROTOCOL))
        elif hello.get('side') != self._peer_side():
            self._refuse('a %s side met a %r side: one world side and one robot side'
                         % (self.side, hello.get('side')))
        elif hello.get('robot') != self.robot:
            self._refuse('the %s side is for robot %r, this %s side for %r: the socket '
                         'paths are crossed' % (self._peer_side(), hello.get('robot'),
                                                self.side, self.robot))
        else:
            self.peer_ready = True
            self._log_info('sim link %s: linked to the %s side' % (self.robot,
                                                                  self._peer_side()))
            if self._on_ready is not None:
                self._on_ready(self)

    def _refuse(self, reason):
        self._limiter.report('refusing', self._log_error,
                             'sim link %s: refusing the link: %s' % (self.robot, reason))
        self._conn.send_json(framing.REFUSE, {'reason': reason})
        self._conn.flush_and_close('refused: %s' % reason)

    def _on_topic(self, announcement):
        channel = announcement.get('channel')
        if not isinstance(channel, int):
            self._refuse('a channel announcement without a channel number: %r' % announcement)
            return
        reason = topics.check_announcement(self.side, announcement, self._local_md5)
        if reason is None:
            self._in_channels[channel] = announcement['topic']
            self._refusals.pop(channel, None)
        else:
            self._in_channels[channel] = None
            self._refusals[channel] = reason
            self._log_error('sim link %s: not relaying %s' % (self.robot, reason))

    def _on_data(self, channel, payload):
        if channel not in self._in_channels:
            self._limiter.report(('unannounced', channel), self._log_error,
                                 'sim link %s: data on channel %d, never announced: dropped'
                                 % (self.robot, channel))
            return
        topic = self._in_channels[channel]
        if topic is None:
            self._limiter.report(('refused', channel), self._log_error,
                                 'sim link %s: dropping %s' % (self.robot,
                                                               self._refusals[channel]))
            return
        self._publish(topic, payload)
