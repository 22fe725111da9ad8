"""The reference page of every package's ROS API, made from the packages' READMEs:

    PYTHONPATH=src/rason/src python3 -m rason_tools.ros_api > docs/reference/ros-api.md

A package README states its nodes' topics, services and parameters under headings that begin
with "ROS API" (such a section runs to the next heading of its level or above). The page holds
those sections package by package, headings moved down to fit under the package's, links
written as plain text (they are relative to the README). The executables a package installs
(catkin_install_python, add_executable) are the names its ROS API is checked against. Needs
no ROS."""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPOSITORY = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(HERE))))
SRC = os.path.join(REPOSITORY, 'src')
REGENERATE = 'PYTHONPATH=src/rason/src python3 -m rason_tools.ros_api > docs/reference/ros-api.md'

_HEADING = re.compile(r'^(#{1,6})\s+(.*?)\s*$')
_FENCE = re.compile(r'^\s*(```|~~~)')
_LINK = re.compile(r'(?<!!)\[([^\]]+)\]\((?!https?://)[^)]*\)')


def packages(src=SRC):
    """The catkin packages under src, by name."""
    return sorted(n for n in os.listdir(src) if os.path.isfile(os.path.join(src, n, 'package.xml')))


def executables(package_dir):
    """The names of the programs a package installs: its catkin_install_python PROGRAMS and its
    add_executable targets."""
    with open(os.path.join(package_dir, 'CMakeLists.txt')) as f:
        cmake = re.sub(r'#.*', '', f.read())
    names = []
    for block in re.findall(r'catkin_install_python\s*\(\s*PROGRAMS(.*?)DESTINATION', cmake, re.S):
        names += [os.path.basename(p) for p in block.split()]
    names += re.findall(r'add_executable\s*\(\s*(\S+)', cmake)
    return sorted(set(names))


def ros_api_sections(readme_text):
    """[(level, lines)] of the README's sections whose heading begins with "ROS API", each its
    heading line and what follows it up to the next heading of its level or above."""
    sections, current, level, fenced = [], None, 0, False
    for line in readme_text.splitlines():
        if _FENCE.match(line):
            fenced = not fenced
        heading = None if fenced else _HEADING.match(line)
        if heading and current is not None and len(heading.group(1)) <= level:
            sections.append((level, current))
            current = None
        if heading and current is None and heading.group(2).startswith('ROS API'):
            level, current = len(heading.group(1)), []
        if current is not None:
            current.append(line)
    if current is not None:
        sections.append((level, current))
    return sections


def _placed(level, lines, top):
    """lines with their headings moved so that the section's own is at level top; fenced code
    kept as it is, links made plain text."""
    out, fenced = [], False
    for line in lines:
        if _FENCE.match(line):
            fenced = not fenced
        heading = None if fenced else _HEADING.match(line)
        if heading:
            line = '#' * min(6, len(heading.group(1)) - level + top) + ' ' + heading.group(2)
        elif not fenced:
            line = _LINK.sub(r'\1', line)
        out.append(line.rstrip())
    while out and not out[-1]:
        out.pop()
    return out


def readme(package, src=SRC):
    with open(os.path.join(src, package, 'README.md'), encoding='utf-8') as f:
        return f.read()


def page(src=SRC):
    """The Markdown page of every package's ROS API sections."""
    out = ['# ROS API of the packages', '',
           "Every node's subscribed and published topics, services and `~params`, as each",
           "package's `README.md` (`src/<package>/`) states them under its \"ROS API\" headings;",
           "`rason_mas`'s parameters are on [rason_mas parameters](parameters.md), the messages on",
           '[Messages](messages.md). Generated from the READMEs: `%s`;' % REGENERATE,
           'a unit test checks that this page matches them and that each README names every program',
           'its package installs.', '']
    for package in packages(src):
        out += ['## %s' % package, '']
        for level, lines in ros_api_sections(readme(package, src)):
            out += _placed(level, lines, 3) + ['']
    return '\n'.join(out)


def main():
    sys.stdout.write(page())
    return 0


if __name__ == '__main__':
    sys.exit(main())
