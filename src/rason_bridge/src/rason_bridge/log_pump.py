"""The log pump: the thread that writes the agents' ``.print`` and Jason's log lines, queued
on the Java side (``rason.core.LogQueue``), off the agents' threads, so printing never
makes an agent wait for Python; no rospy. It takes the queued lines in batches, each one
call into Java, and writes each batch at once."""
import threading

#: How long the thread lets lines gather once one is queued (s), and how many it takes at once.
POLL = 0.02
BATCH = 500
#: How long it waits in Java for a line before it looks at its stop flag (ms).
IDLE_WAIT_MS = 500

#: java.util.logging's levels (SEVERE, WARNING, INFO) -> the level written; below INFO: debug.
_LEVELS = ((1000, 'error'), (900, 'warn'), (800, 'info'))


def level_name(java_level):
    """``'error'``, ``'warn'``, ``'info'`` or ``'debug'`` for a java.util.logging level."""
    return next((name for at_least, name in _LEVELS if java_level >= at_least), 'debug')


def batch_lines(batch):
    """``[(level_name, text), ...]`` of a ``LogQueue.Batch`` (levels, code-point ends, text)."""
    levels, ends, text = _ints(batch.levels()), _ints(batch.ends()), str(batch.text())
    lines, start = [], 0
    for level, end in zip(levels, ends):
        lines.append((level_name(level), text[start:end]))
        start = end
    return lines


def _ints(array):
    try:  # a Java int[] exposes its memory: read at once, not element by element through JPype
        return memoryview(array).cast('B').cast('i').tolist()
    except (TypeError, ValueError, NotImplementedError):
        return [int(i) for i in array]


class LogPump(object):
    """
    :param lines: the Java ``LogQueue`` (``drainBatch(max)``, ``takeDropped()``,
        ``awaitLines(ms)``: parks this thread in Java, without the GIL, until a line comes)
    :param write: ``write([(level_name, text), ...])`` writes lines in order
    """

    def __init__(self, lines, write):
        self._lines = lines
        self._write = write
        self._stop = threading.Event()

    def start(self):
        threading.Thread(target=self._run, name='rason_log', daemon=True).start()

    def _run(self):
        while not self._stop.is_set():
            if not self.drain() and self._lines.awaitLines(IDLE_WAIT_MS):
                self._stop.wait(POLL)  # the lines of the next moments go in the same batch

    def close(self, detach):
        """Stop the thread, ``detach()`` Java's queue (it logs to stderr from then on), write what it still holds."""
        self._stop.set()
        detach()
        while self.drain():
            pass

    def drain(self):
        """Writes the queued lines; returns how many there were."""
        lines = batch_lines(self._lines.drainBatch(BATCH))
        dropped = int(self._lines.takeDropped())
        if dropped:
            lines.append(('warn', '%d log lines of the agents were dropped: they came faster than rosout took them'
                          % dropped))
        if lines:
            self._write(lines)
        return len(lines) - (1 if dropped else 0)
