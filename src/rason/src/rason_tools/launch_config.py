"""``rosrun rason launch_config FILE.launch KEY=VALUE ...``: one line of a launch's effective
configuration, printed once as the launch starts, so that what roslaunch silently accepted is on
screen: an argument misspelt (``robto:=helper``) leaves its default showing. Each launch file
that users start runs it as its first node, giving it the values it resolved (the robot's
namespace, the program, the wiring file, the fault, the simulator's rate and world...).

``run_launch`` prints the same lines before any node starts and does not start these nodes.

Once printed, the process becomes ``sleep``: it stays in the launch (roslaunch would report
a node that ends) at no cost, and ends with it."""
import os
import shlex
import sys

import yaml

PREFIX = '[configuration] '


def world_robots(path):
    """The robots a simulator world file names, or None when it cannot be read."""
    try:
        with open(path) as f:
            robots = (yaml.safe_load(f) or {}).get('robots')
    except (OSError, yaml.YAMLError, AttributeError):
        return None
    return [str(r) for r in robots] if isinstance(robots, list) else None


def line(argv):
    """The configuration line of ``FILE.launch KEY=VALUE ...`` (roslaunch's ``__name:=`` and
    ``__log:=`` left out): ``[configuration] FILE.launch: key value, key value``; a ``world``
    also names its robots."""
    words = [a for a in argv if ':=' not in a]
    if not words:
        return PREFIX + '(nothing given)'
    items = []
    for word in words[1:]:
        key, _, value = word.partition('=')
        shown = '%s %s' % (key, value if value else '(empty)')
        if key == 'world':
            robots = world_robots(value)
            shown += ' (robots %s)' % ', '.join(robots) if robots is not None else ' (cannot be read)'
        items.append(shown)
    return PREFIX + '%s: %s' % (words[0], ', '.join(items))


def node_line(node_args):
    """The line of a launch_config node whose ``args`` attribute (as in the launch file) is
    ``node_args``: what ``run_launch`` prints in its place."""
    return line(shlex.split(node_args or ''))


def main(argv=None):
    print(line(sys.argv[1:] if argv is None else argv))
    sys.stdout.flush()
    os.execvp('sleep', ['sleep', 'infinity'])
