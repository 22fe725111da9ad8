"""docs/reference/ros-api.md is what rason_tools.ros_api makes of the package READMEs, and every
package README has a "ROS API" section naming each program its package installs."""
import os
import re
import textwrap

from rason_tools import ros_api
from rason_tools.ros_api import REGENERATE, REPOSITORY, SRC, executables, packages, readme, ros_api_sections

PAGE = os.path.join(REPOSITORY, 'docs', 'reference', 'ros-api.md')


def test_the_committed_page_is_what_the_readmes_make():
    with open(PAGE, encoding='utf-8') as f:
        committed = f.read()
    assert committed == ros_api.page(), 'docs/reference/ros-api.md is stale: %s' % REGENERATE


def test_every_package_readme_has_a_ros_api_naming_each_program_it_installs():
    found = packages()
    assert {'rason', 'rason_bridge', 'rason_wiring', 'rason_sim'} <= set(found), found
    missing = {}
    for package in found:
        text = '\n'.join(line for _, lines in ros_api_sections(readme(package)) for line in lines)
        if not text:
            missing[package] = 'no "ROS API" section'
            continue
        unnamed = [e for e in executables(os.path.join(SRC, package)) if not re.search(r'`%s[`\s]' % re.escape(e), text)]
        if unnamed:
            missing[package] = 'not named in its ROS API: %s' % ', '.join(unnamed)
    assert not missing, missing


def test_a_section_runs_to_the_next_heading_of_its_level_and_code_is_not_a_heading():
    text = textwrap.dedent('''\
        # pkg
        intro
        ## ROS API of `a_node`
        | subscribes | `odom` |
        ```sh
        # a comment, not a heading
        ```
        ### Parameters
        `~rate` 10 Hz, see [the guide](../docs/guide.md) or [site](https://example.org/)
        ## Tests
        not part of it
        ''')
    (level, lines), = ros_api_sections(text)
    assert level == 2
    assert lines[0] == '## ROS API of `a_node`' and lines[-1].startswith('`~rate`')
    placed = ros_api._placed(level, lines, 3)
    assert placed[0] == '### ROS API of `a_node`'
    assert '# a comment, not a heading' in placed
    assert '#### Parameters' in placed
    assert placed[-1] == '`~rate` 10 Hz, see the guide or [site](https://example.org/)'


def test_the_programs_of_a_package_come_from_its_cmakelists(tmp_path):
    (tmp_path / 'CMakeLists.txt').write_text(textwrap.dedent('''\
        catkin_install_python(PROGRAMS scripts/one_node
          scripts/tool.py
          DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
        # add_executable(commented_out src/x.cpp)
        add_executable(sim_node src/sim.cpp)
        '''))
    assert executables(str(tmp_path)) == ['one_node', 'sim_node', 'tool.py']
