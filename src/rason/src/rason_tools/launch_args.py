"""The reference page of the launch files' arguments, made from the launch files themselves:

    PYTHONPATH=src/rason/src python3 -m rason_tools.launch_args > docs/reference/launch-args.md

A launch file's arguments are its top-level ``<arg>`` elements without ``value`` (those are
the file's own constants): each with its default (none: the argument is required) and its
``doc``. The page lists the files of ``src/rason/launch`` and the tutorial's launch file.
Needs no ROS."""
import glob
import os
import re
import sys
import xml.etree.ElementTree as ElementTree

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE = os.path.dirname(os.path.dirname(HERE))     # src/rason
REPOSITORY = os.path.dirname(os.path.dirname(PACKAGE))
REGENERATE = 'PYTHONPATH=src/rason/src python3 -m rason_tools.launch_args > docs/reference/launch-args.md'


def launch_files(package=PACKAGE):
    """The user-facing launch files: launch/*.launch and tutorial/*.launch, by name."""
    found = glob.glob(os.path.join(package, 'launch', '*.launch')) + glob.glob(
        os.path.join(package, 'tutorial', '*.launch'))
    return sorted(found, key=os.path.basename)


def launch_args(path):
    """(summary, [(name, default or None, doc)]) of a launch file, its arguments in file order;
    summary is the file's first comment, on one line."""
    root = ElementTree.parse(path).getroot()
    args = [(a.get('name'), a.get('default'), ' '.join((a.get('doc') or '').split()))
            for a in root.findall('arg') if a.get('value') is None]
    return _first_comment(path), args


def _first_comment(path):
    with open(path) as f:
        match = re.search(r'<!--(.*?)-->', f.read(), re.S)
    return ' '.join(match.group(1).split()) if match else ''


def _cell(text):
    return text.replace('|', '\\|')


def _code(text):
    return '`%s`' % text if text else '`""`'


def page(paths=None):
    """The Markdown page for ``paths`` (default: :func:`launch_files`)."""
    paths = launch_files() if paths is None else paths
    out = ['# Launch arguments', '',
           'Every argument a user can set on the launch files of `src/rason/launch` (also `launch/` at',
           "the top of the repository) and on the tutorial's, with its default and what it does, as",
           'the files declare them (`roslaunch --ros-args rason FILE.launch` lists the same). Generated',
           'from the files: `%s`;' % REGENERATE,
           'a unit test checks that this page matches them. What each file starts is under',
           '[Launch files](launch-files.md).', '']
    for path in paths:
        summary, args = launch_args(path)
        out += ['## %s' % os.path.basename(path), '']
        if summary:
            out += [_cell(summary), '']
        if not args:
            out += ['No arguments.', '']
            continue
        out += ['| argument | default | what it does |', '|---|---|---|']
        for name, default, doc in args:
            shown = 'required' if default is None else _code(_cell(default))
            out.append('| `%s` | %s | %s |' % (name, shown, _cell(doc)))
        out.append('')
    return '\n'.join(out)


def main():
    sys.stdout.write(page())
    return 0


if __name__ == '__main__':
    sys.exit(main())
