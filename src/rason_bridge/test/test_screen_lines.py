"""screen_lines: a batch of lines printed as rosgraph's RosStreamHandler prints each (same text,
streams and colours), one write per run of lines to a stream (no ROS master)."""
import io
import logging

import pytest

roslogging = pytest.importorskip('rosgraph.roslogging')

from rason_bridge.rosout_writer import RosoutWriter  # noqa: E402
from rason_bridge.screen_lines import emit_batch  # noqa: E402

WALL = 1796600000.123456
NODE = '/r1/rason_mas'
FULL = ('${severity}|${time}|${walltime}|${thread}|${logger}|${file}|${line}|${function}|${node}|'
        '${time:%Y}|${walltime:%Y}|${message}|end')


class Stream(io.StringIO):
    """A stream that counts its writes, on a terminal or not."""

    def __init__(self, tty=False):
        super().__init__()
        self.tty, self.writes = tty, 0

    def isatty(self):
        return self.tty

    def write(self, text):
        self.writes += 1
        return super().write(text)


def _records(lines):
    return [logging.LogRecord('rosout', level, 'rosout_writer.py', 0, text, None, None, 'write')
            for level, text in lines]


LINES = [(logging.INFO, '[bob] hello'), (logging.DEBUG, 'detail'), (logging.WARNING, '50% done'),
         (logging.ERROR, 'jason failed'), (logging.INFO, '[bob] again'), (logging.CRITICAL, 'the end')]


def _handlers(tty, sim_time):
    """rosgraph's handler and the batched one, each with streams of its own."""
    pair = []
    for _ in range(2):
        h = roslogging.RosStreamHandler(colorize=True, stdout=Stream(tty), stderr=Stream(tty))
        if sim_time is not None:
            h._get_time, h._is_wallclock = (lambda: sim_time), (lambda: False)
        else:
            h._is_wallclock = lambda: True
        pair.append(h)
    return pair


def _both(monkeypatch, fmt=None, tty=False, sim_time=None, lines=LINES):
    if fmt is None:
        monkeypatch.delenv('ROSCONSOLE_FORMAT', raising=False)
    else:
        monkeypatch.setenv('ROSCONSOLE_FORMAT', fmt)
    monkeypatch.setattr(roslogging.time, 'time', lambda: WALL)
    import rospy
    monkeypatch.setattr(rospy, 'get_name', lambda: NODE)
    rosgraphs, batched = _handlers(tty, sim_time)
    for record in _records(lines):
        rosgraphs.handle(record)
    emit_batch(batched, _records(lines), roslogging._logging_to_rospy_names, roslogging._color_reset, NODE,
               wall=lambda: WALL)
    return rosgraphs, batched


@pytest.mark.parametrize('fmt', [None, FULL, '${message}', '${node} says ${message} (${message})'])
@pytest.mark.parametrize('tty', [False, True])
@pytest.mark.parametrize('sim_time', [None, 12.5])
def test_the_text_streams_and_colours_are_rosgraphs(monkeypatch, fmt, tty, sim_time):
    rosgraphs, batched = _both(monkeypatch, fmt, tty, sim_time)
    assert batched._stdout.getvalue() == rosgraphs._stdout.getvalue()
    assert batched._stderr.getvalue() == rosgraphs._stderr.getvalue()
    assert batched._stdout.getvalue().count('\n') == 3 and batched._stderr.getvalue().count('\n') == 3


def test_one_write_per_run_of_lines_to_a_stream(monkeypatch):
    rosgraphs, batched = _both(monkeypatch)
    assert rosgraphs._stdout.writes == 3 and rosgraphs._stderr.writes == 3
    # stdout: hello, detail; stderr: 50% done, failed; stdout: again; stderr: the end
    assert batched._stdout.writes == 2 and batched._stderr.writes == 2


def test_the_handlers_level_holds(monkeypatch):
    rosgraphs, batched = _handlers(False, None)
    batched.setLevel(logging.WARNING)
    emit_batch(batched, _records(LINES), roslogging._logging_to_rospy_names, roslogging._color_reset, NODE)
    assert batched._stdout.getvalue() == ''
    assert [l.split(': ', 1)[1] for l in batched._stderr.getvalue().splitlines()] == [
        '50% done', 'jason failed', 'the end']


def test_a_tag_in_a_lines_own_text_is_printed_as_it_is(monkeypatch):
    rosgraphs, batched = _both(monkeypatch, lines=[(logging.INFO, 'cost ${time} and ${node}')])
    assert batched._stdout.getvalue() == '[INFO] [%f]: cost ${time} and ${node}\n' % WALL
    assert rosgraphs._stdout.getvalue() != batched._stdout.getvalue()  # rosgraph fills them in


def test_the_writer_hands_a_batch_to_the_emitter_of_the_handlers_class():
    logger = logging.getLogger('test_screen_lines')
    logger.propagate = False
    screen = roslogging.RosStreamHandler(stdout=Stream(), stderr=Stream())
    logger.handlers[:] = [screen]
    logger.setLevel(logging.INFO)
    batches = []
    writer = RosoutWriter(logger, type(None), lambda lines, topics: None, lambda: [], lambda: False,
                          emitters={roslogging.RosStreamHandler: lambda h, records: batches.append(
                              (h, [r.getMessage() for r in records]))})
    writer.write([('info', 'a'), ('debug', 'quiet'), ('warn', 'b')])
    assert batches == [(screen, ['a', 'b'])]
