"""Writes batches of the agents' log lines where ``rospy.loginfo`` & co. would (the handlers
of the ``rosout`` logger and of its ancestors: the screen and the node's log file; and
/rosout), without rospy's costs per line: its search for the caller's frame, and the
master's ``/rosout_disable_topics_generation`` parameter, which rospy asks the master for on
every line while the parameter is unset (its cache keeps no "unset"); no rospy.

A batch goes to a plain file or stream handler (the node's log file) as one write and one
flush, and to /rosout as one publication of all its messages."""
import contextlib
import logging
import logging.handlers
import time

#: How long a value of the parameter is used before it is asked again (s).
PARAM_PERIOD = 1.0

#: The level names of :func:`rason_bridge.log_pump.level_name` -> logging's levels.
LEVELS = {'debug': logging.DEBUG, 'info': logging.INFO, 'warn': logging.WARNING, 'error': logging.ERROR}


class RosoutWriter(object):
    """
    :param logger: the ``rosout`` logger: a line below its level is not written (as logging
        does), the others go to its handlers and, while it propagates, to its ancestors'
    :param rosout_handler: the class of rospy's handler that publishes to /rosout: it is
        skipped, the line published here instead, while the logger has one
    :param publish: ``publish([(level_name, text), ...], topics)`` publishes one /rosout
        message per line, in order
    :param topics: ``topics()`` -> the node's topics, which a rosout message carries
    :param topics_disabled: ``topics_disabled()`` -> the parameter; asked at most every
        :data:`PARAM_PERIOD` s (then rosout messages carry no topics)
    :param emitters: ``{handler class: emit(handler, records)}``: how a batch goes to a handler
        of that class (e.g. :func:`rason_bridge.screen_lines.emit_batch` for the screen's)
    """

    def __init__(self, logger, rosout_handler, publish, topics, topics_disabled, clock=time.monotonic,
                 emitters=None):
        self._logger = logger
        self._emitters = list((emitters or {}).items())
        self._rosout_handler = rosout_handler
        self._publish = publish
        self._topics = topics
        self._topics_disabled = topics_disabled
        self._clock = clock
        self._disabled, self._asked = False, None

    def write(self, lines):
        """Writes ``[(level_name, text), ...]`` in order."""
        handlers, to_rosout = self._handlers()
        kept, records = [], []
        for level_name, text in lines:
            level = LEVELS[level_name]
            if self._logger.isEnabledFor(level):
                kept.append((level_name, text))
                records.append(logging.LogRecord(self._logger.name, level, __file__, 0, text, None, None, 'write'))
        if not kept:
            return
        for handler in handlers:
            emit = next((e for cls, e in self._emitters if isinstance(handler, cls)), None)
            if emit is not None:
                emit(handler, records)
            elif type(handler) in _BATCHED:
                _emit_batch(handler, records)
            else:
                for record in records:
                    if record.levelno >= handler.level:
                        handler.handle(record)
        if to_rosout:
            self._publish(kept, '' if self._topics_off() else self._topics())

    def _handlers(self):
        handlers, to_rosout, logger = [], False, self._logger
        while logger:
            for h in logger.handlers:
                if isinstance(h, self._rosout_handler):
                    to_rosout = True
                else:
                    handlers.append(h)
            logger = logger.parent if logger.propagate else None
        return handlers, to_rosout

    def _topics_off(self):
        now = self._clock()
        if self._asked is None or now - self._asked >= PARAM_PERIOD:
            self._asked = now
            try:
                self._disabled = bool(self._topics_disabled())
            except Exception:  # the master is gone: the last value stands
                pass
        return self._disabled


#: Handlers whose emit is a format, a write and a flush (and, rotating, a size check): a batch
#: is written to them at once. Others get each line on its own.
_BATCHED = (logging.StreamHandler, logging.FileHandler, logging.handlers.RotatingFileHandler)


def _emit_batch(handler, records):
    """The records a handler would take, written as ``handler.handle`` would, one write for all
    (a rotating file rolls over before the batch that would take it past its size)."""
    records = [r for r in records if r.levelno >= handler.level and handler.filter(r)]
    if not records:
        return
    with emitting(handler, records[0]):
        text = ''.join(handler.format(r) + handler.terminator for r in records)
        if isinstance(handler, logging.FileHandler):
            _open(handler)
            if not handler.stream:
                return  # closed for good, as FileHandler.emit decides
        if isinstance(handler, logging.handlers.RotatingFileHandler) and handler.maxBytes > 0:
            handler.stream.seek(0, 2)
            if handler.stream.tell() + len(text) >= handler.maxBytes:
                handler.doRollover()
                _open(handler)
        handler.stream.write(text)
        handler.flush()


@contextlib.contextmanager
def emitting(handler, record):
    """Inside, a batch is written to ``handler`` as logging's handlers write a record: under the
    handler's lock, an error handed to its ``handleError`` (with ``record``), not raised."""
    handler.acquire()
    try:
        yield
    except RecursionError:
        raise
    except Exception:
        handler.handleError(record)
    finally:
        handler.release()


def _open(handler):
    if handler.stream is None and (handler.mode != 'w' or not handler._closed):
        handler.stream = handler._open()
