"""What rosgraph's ``RosStreamHandler`` (a node's screen) prints for a batch of an agent's log
lines, written with one write per run of lines bound for the same stream: the handler fills
its format (``ROSCONSOLE_FORMAT``) anew for every line, with a dozen string replacements and a
look-up of the node's name, and writes each line on its own.

The text, the streams (below WARNING to stdout, the rest to stderr) and the colours (on a
terminal) are the handler's. The times are taken once per batch. One difference: a
``${...}`` tag inside a line's own text is printed as it is, where the handler would replace
it. No rospy: the handler's tables and clocks are handed in or read off the handler."""
import logging
import os
import time

from rason_bridge.rosout_writer import emitting

#: rosgraph's format when ROSCONSOLE_FORMAT is not set.
DEFAULT_FORMAT = '[${severity}] [${time}]: ${message}'
_MESSAGE = '\0'   # stands for ${message} while the other tags are filled in


def _fill_times(text, tag, stamp, sim):
    """``${tag}`` as the handler writes it (``stamp``, then the ROS time ``sim`` when it is not
    the wall clock), and ``${tag:FORMAT}`` as strftime(FORMAT) (then ``sim`` for ``time``)."""
    text = text.replace('${%s}' % tag, stamp)
    opening = '${%s:' % tag
    while opening in text:
        start = text.index(opening) + len(opening)
        fmt = text[start:text.index('}', start)]
        text = text.replace(opening + fmt + '}', time.strftime(fmt) + sim)
    return text


def template(fmt, severity, node, record, wall, sim_time):
    """The line the handler would print for ``record`` with its message left out: the parts
    around each ``${message}``.

    :param wall: the wall clock (s)
    :param sim_time: the ROS time (s) when it is not the wall clock, else None
    """
    stamp = '%f' % wall
    sim = '' if sim_time is None else ', %f' % sim_time
    text = fmt.replace('${severity}', severity).replace('${message}', _MESSAGE)
    text = _fill_times(text, 'walltime', stamp, '')
    for tag, value in (('thread', record.thread), ('logger', record.name), ('file', record.pathname),
                       ('line', record.lineno), ('function', record.funcName), ('node', node)):
        text = text.replace('${%s}' % tag, str(value))
    return _fill_times(text, 'time', stamp + sim, sim).split(_MESSAGE)


def emit_batch(handler, records, names, reset, node, environ=os.environ, wall=time.time):
    """Print ``records`` as ``handler`` would, one write per run of lines to the same stream.

    :param handler: a rosgraph ``RosStreamHandler``
    :param names: rosgraph's level name -> (severity, colour or None)
    :param reset: rosgraph's colour reset
    :param node: the node's name (``${node}``)
    """
    records = [r for r in records if r.levelno >= handler.level and handler.filter(r)]
    if not records:
        return
    fmt = environ.get('ROSCONSOLE_FORMAT', DEFAULT_FORMAT)
    now = wall()
    sim_time = None
    if handler._get_time is not None and not handler._is_wallclock():
        sim_time = handler._get_time()
    templates = {}
    runs = []   # [stream, [(colour, line)]]
    for record in records:
        severity, colour = names[record.levelname]
        key = (record.levelname, record.thread, record.name, record.pathname, record.lineno, record.funcName)
        parts = templates.get(key)
        if parts is None:
            parts = templates[key] = template(fmt, severity, node, record, now, sim_time)
        stream = handler._stdout if record.levelno < logging.WARNING else handler._stderr
        if not runs or runs[-1][0] is not stream:
            runs.append([stream, []])
        runs[-1][1].append((colour, record.getMessage().join(parts) + '\n'))
    with emitting(handler, records[0]):
        for stream, lines in runs:
            if handler._colorize and hasattr(stream, 'isatty') and stream.isatty():
                stream.write(''.join(colour + line + reset if colour else line for colour, line in lines))
            else:
                stream.write(''.join(line for _, line in lines))
