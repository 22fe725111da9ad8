"""docs/reference/launch-args.md is what rason_tools.launch_args makes of the launch files, and
the launch files declare every optional argument with a default and a doc, so that
``roslaunch --ros-args`` lists as required only what is (needs the workspace for that part)."""
import os
import textwrap

import pytest

from rason_tools import launch_args
from rason_tools.launch_args import REGENERATE, REPOSITORY, launch_files, page

PAGE = os.path.join(REPOSITORY, 'docs', 'reference', 'launch-args.md')
TRULY_REQUIRED = {('robot.launch', 'ns'), ('case_study_robot.launch', 'role'), ('robot_host.launch', 'robot'),
                  ('sim_link.launch', 'robot')}


def test_the_committed_page_is_what_the_launch_files_make():
    with open(PAGE) as f:
        committed = f.read()
    assert committed == page(), 'docs/reference/launch-args.md is stale: %s' % REGENERATE


def test_the_page_follows_a_launch_file_both_ways(tmp_path):
    path = tmp_path / 'mine.launch'
    path.write_text(textwrap.dedent('''\
        <launch>
          <!-- what mine starts -->
          <arg name="speed" default="0.2" doc="m/s | at most"/>
          <arg name="name" doc="the robot"/>
          <arg name="derived" value="$(arg speed)"/>
        </launch>'''))
    before = page([str(path)])
    assert '## mine.launch\n\nwhat mine starts\n' in before
    assert '| `speed` | `0.2` | m/s \\| at most |' in before
    assert '| `name` | required | the robot |' in before
    assert 'derived' not in before             # a value= arg is the file's own, not an argument
    path.write_text(path.read_text().replace('<arg name="speed" default="0.2" doc="m/s | at most"/>',
                                             '<arg name="mode" default="" doc="new"/>'))
    after = page([str(path)])
    assert 'speed' not in after
    assert '| `mode` | `""` | new |' in after


def test_every_optional_argument_has_a_default_and_a_doc():
    missing = []
    for path in launch_files():
        name = os.path.basename(path)
        for arg, default, doc in launch_args.launch_args(path)[1]:
            if default is None and (name, arg) not in TRULY_REQUIRED:
                missing.append('%s %s: no default' % (name, arg))
            if default == '':
                missing.append('%s %s: an empty default (roslaunch --ros-args calls it required)' % (name, arg))
            if not doc:
                missing.append('%s %s: no doc' % (name, arg))
    assert not missing


def test_roslaunch_lists_as_required_only_what_is():
    arg_dump = pytest.importorskip('roslaunch.arg_dump')
    pytest.importorskip('rospkg').RosPack().get_path('rason')   # $(find rason) must resolve
    for path in launch_files():
        name = os.path.basename(path)
        listed = arg_dump.get_args([path])
        required = {(name, arg) for arg, (_, default) in listed.items() if not default}
        assert required == {r for r in TRULY_REQUIRED if r[0] == name}, name
        ours = {arg for arg, _, _ in launch_args.launch_args(path)[1]}
        assert ours <= set(listed), name
