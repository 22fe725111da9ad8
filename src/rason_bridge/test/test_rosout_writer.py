"""RosoutWriter: the agents' lines reach the rosout logger's handlers and /rosout as rospy's
loggers would send them (no ROS master)."""
import logging

from rason_bridge.rosout_writer import PARAM_PERIOD, RosoutWriter


class Kept(logging.Handler):
    def __init__(self, level=logging.NOTSET):
        super().__init__(level)
        self.records = []

    def emit(self, record):
        self.records.append((record.levelno, record.getMessage()))


class ToRosout(Kept):
    """Stands for rospy's RosOutHandler: the writer publishes instead of calling it."""


def _logger(name, level=logging.INFO):
    parent = logging.getLogger('test_rosout_writer')
    parent.handlers[:] = [Kept()]
    parent.propagate = False
    logger = parent.getChild(name)
    logger.handlers[:] = [Kept(), ToRosout()]
    logger.setLevel(level)
    return logger, logger.handlers[0], parent.handlers[0], logger.handlers[1]


def _writer(logger, published, disabled=lambda: False, clock=lambda: 0.0):
    return RosoutWriter(logger, ToRosout, lambda lines, topics: published.extend((l, t, topics) for l, t in lines),
                        lambda: ['/rosout', '/jason/action'], disabled, clock)


def test_every_line_goes_to_the_handlers_the_parent_handlers_and_rosout_in_order():
    logger, own, parents, rosout = _logger('order')
    published = []
    _writer(logger, published).write([('info', '[bob] p1'), ('error', 'jason failed'), ('warn', '50% done')])
    expected = [(logging.INFO, '[bob] p1'), (logging.ERROR, 'jason failed'), (logging.WARNING, '50% done')]
    assert own.records == expected and parents.records == expected
    assert rosout.records == []  # published directly, not through rospy's handler
    assert published == [('info', '[bob] p1', ['/rosout', '/jason/action']),
                         ('error', 'jason failed', ['/rosout', '/jason/action']),
                         ('warn', '50% done', ['/rosout', '/jason/action'])]


def test_lines_below_the_loggers_level_go_nowhere_and_a_handlers_level_holds():
    logger, own, parents, _ = _logger('levels', level=logging.INFO)
    own.setLevel(logging.ERROR)
    published = []
    _writer(logger, published).write([('debug', 'quiet'), ('info', 'said'), ('error', 'loud')])
    assert own.records == [(logging.ERROR, 'loud')]
    assert parents.records == [(logging.INFO, 'said'), (logging.ERROR, 'loud')]
    assert [p[1] for p in published] == ['said', 'loud']


def test_without_rospys_rosout_handler_nothing_is_published():
    logger, own, _, rosout = _logger('no_rosout')
    logger.removeHandler(rosout)
    published = []
    _writer(logger, published).write([('info', 'only on screen')])
    assert own.records == [(logging.INFO, 'only on screen')] and published == []


def test_the_topics_parameter_is_asked_at_most_once_a_period_and_empties_the_topics():
    logger = _logger('param')[0]
    published, asked, now = [], [], [0.0]

    def disabled():
        asked.append(now[0])
        return True
    writer = _writer(logger, published, disabled, lambda: now[0])
    for t in (0.0, 0.1, PARAM_PERIOD / 2, PARAM_PERIOD + 0.1):
        now[0] = t
        writer.write([('info', 'a'), ('info', 'b')])
    assert asked == [0.0, PARAM_PERIOD + 0.1]
    assert {p[2] for p in published} == {''}


def test_a_failing_parameter_lookup_keeps_the_last_value():
    logger = _logger('param_fails')[0]
    published, now = [], [0.0]
    answers = iter([True])

    def disabled():
        return next(answers)  # StopIteration the second time: the master is gone
    writer = _writer(logger, published, disabled, lambda: now[0])
    writer.write([('info', 'a')])
    now[0] = PARAM_PERIOD * 2
    writer.write([('info', 'b')])
    assert [p[2] for p in published] == ['', '']


def test_a_file_handler_gets_a_batch_formatted_in_order_at_its_level(tmp_path):
    import logging.handlers
    logger = _logger('file')[0]
    path = tmp_path / 'node.log'
    handler = logging.handlers.RotatingFileHandler(str(path))
    handler.setFormatter(logging.Formatter('%(levelname)s %(message)s'))
    handler.setLevel(logging.WARNING)
    logger.addHandler(handler)
    try:
        _writer(logger, []).write([('info', 'a'), ('warn', 'b'), ('error', 'c\nd')])
        assert path.read_text() == 'WARNING b\nERROR c\nd\n'
    finally:
        logger.removeHandler(handler)
        handler.close()


def test_a_rotating_file_rolls_over_before_a_batch_that_would_pass_its_size(tmp_path):
    import logging.handlers
    logger = _logger('rotating')[0]
    path = tmp_path / 'node.log'
    handler = logging.handlers.RotatingFileHandler(str(path), maxBytes=20, backupCount=1)
    logger.addHandler(handler)
    try:
        writer = _writer(logger, [])
        writer.write([('info', 'first line')])
        writer.write([('info', 'second'), ('info', 'third')])
        assert (tmp_path / 'node.log.1').read_text() == 'first line\n'
        assert path.read_text() == 'second\nthird\n'
    finally:
        logger.removeHandler(handler)
        handler.close()
