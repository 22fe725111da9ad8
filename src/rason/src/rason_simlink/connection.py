"""One live link: a socket, a reader thread handing records on, a writer thread sending them.

Sends never block the caller (a ROS callback): data waits in a queue bounded in bytes and is
dropped, counted, when the peer does not keep up; control records are never dropped. A
peer that stops reading for send_timeout seconds, closes, or sends something that is not a
record ends the link; on_closed(reason) is then called once.
"""
import collections
import socket
import threading

from . import framing

RECV_SIZE = 1 << 20


class Connection:

    def __init__(self, sock, on_record, on_closed, max_queued_bytes=16 << 20,
                 send_timeout=10.0, max_body=framing.MAX_BODY):
        self._sock = sock
        self._on_record = on_record
        self._on_closed = on_closed
        self._max_queued = max_queued_bytes
        self._max_body = max_body
        self._queue = collections.deque()
        self._queued_bytes = 0
        self._cond = threading.Condition()
        self._closed = False
        self._close_reason = None
        self.dropped = 0
        sock.settimeout(send_timeout)
        self._reader = threading.Thread(target=self._read_loop, daemon=True)
        self._writer = threading.Thread(target=self._write_loop, daemon=True)

    def start(self):
        self._reader.start()
        self._writer.start()
        return self

    @property
    def closed(self):
        return self._closed

    def send_json(self, kind, value):
        self._put((framing.json_record(kind, value),), 0)

    def send_data(self, channel, payload):
        """False if the message was dropped (queue full, or a body over the cap)."""
        try:
            parts = framing.data_parts(channel, payload, self._max_body)
        except framing.FramingError:
            self.dropped += 1
            return False
        return self._put(parts, len(payload))

    def _put(self, parts, size):
        with self._cond:
            if self._closed:
                return False
            if size and self._queued_bytes + size > self._max_queued:
                self.dropped += 1
                return False
            self._queue.append((parts, size))
            self._queued_bytes += size
            self._cond.notify()
            return True

    def close(self, reason='closed here'):
        with self._cond:
            if self._closed:
                return
            self._closed = True
            self._close_reason = reason
            self._queue.clear()
            self._queued_bytes = 0
            self._cond.notify_all()
        try:
            self._sock.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass
        self._sock.close()
        self._on_closed(reason)

    def flush_and_close(self, reason, timeout=1.0):
        """Sends what is queued (a REFUSE, say), then closes."""
        with self._cond:
            self._cond.wait_for(lambda: not self._queue or self._closed, timeout)
        self.close(reason)

    def _write_loop(self):
        while True:
            with self._cond:
                self._cond.wait_for(lambda: self._queue or self._closed)
                if self._closed:
                    return
                parts, size = self._queue[0]
            try:
                for part in parts:
                    self._sock.sendall(part)
            except socket.timeout:
                self.close('the peer stopped reading (send timed out)')
                return
            except (BrokenPipeError, ConnectionResetError):
                self.close('the peer closed the link (on sending)')
                return
            except OSError as err:
                self.close('send failed: %s' % err)
                return
            with self._cond:
                if self._queue:
                    self._queue.popleft()
                    self._queued_bytes -= size
                self._cond.notify_all()

    def _read_loop(self):
        reader = framing.RecordReader(self._max_body)
        while not self._closed:
            try:
                data = self._sock.recv(RECV_SIZE)
            except socket.timeout:
                continue
            except ConnectionResetError:
                self.close('the peer closed the link (reset)')
                return
            except OSError as err:
                self.close('receive failed: %s' % err)
                return
            if not data:
                self.close('the peer closed the link')
                return
            try:
                records = reader.feed(data)
            except framing.FramingError as err:
                self.close(str(err))
                return
            for kind, body in records:
                if self._closed:
                    return
                try:
                    self._on_record(kind, body)
                except Exception as err:  # a handler bug must not leave a half-dead link
                    self.close('record handler failed: %r' % err)
                    return
