"""Unit tests of rason_wiring.layout: a wiring node without ~perceptions (~actions) says where it
looked, what it found near by and what to change, for the real files of both layouts loaded in
the wrong place (no ROS master: parameter names as the server lists them)."""
import os

import pytest
import yaml

from rason_wiring import layout
from rason_wiring.config import ConfigError

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PATROL = os.path.join(REPO, 'rason', 'agents', 'patrol', 'wiring.yaml')        # wrapped
TUTORIAL = os.path.join(REPO, 'rason', 'tutorial', 'perceptions.yaml')        # top-level perceptions:


def loaded(path, under):
    """The parameter names a ``<rosparam command="load" file=path>`` makes under ``under``
    (a dict is listed by its leaves, as rospy.get_param_names lists it)."""
    with open(path) as f:
        content = yaml.safe_load(f)
    names = []

    def walk(prefix, value):
        if isinstance(value, dict) and value:
            for k, v in value.items():
                walk(prefix + '/' + str(k), v)
        else:
            names.append(prefix)
    walk(under.rstrip('/'), content)
    return names


def test_the_real_layouts_are_the_two_this_module_explains():
    with open(PATROL) as f:
        assert set(yaml.safe_load(f)) == {'generic_decomposer', 'generic_synthesizer'}
    with open(TUTORIAL) as f:
        assert 'perceptions' in yaml.safe_load(f)


def test_a_wrapped_file_given_to_robot_launch_says_so():
    names = loaded(PATROL, '/rover/generic_synthesizer') + ['/run_id']
    assert layout.missing('perceptions', '/rover/generic_synthesizer', '/rover/', names) == (
        '~perceptions is not set (looked for /rover/generic_synthesizer/perceptions, found '
        '/rover/generic_synthesizer/generic_synthesizer/perceptions): the wiring file loaded into this node has '
        '`generic_synthesizer:` at its top level (its top-level keys: generic_decomposer, generic_synthesizer), '
        'the layout for loading into the robot\'s namespace, as patrol.launch loads agents/patrol/wiring.yaml; '
        'a file given as robot.launch perceptions:=FILE needs `perceptions:` at its top level: remove the '
        '`generic_synthesizer:` line and unindent what it holds')


def test_a_wrapped_actions_file_loaded_into_the_decomposer_says_so():
    names = loaded(PATROL, '/rover/generic_decomposer')
    text = layout.missing('actions', '/rover/generic_decomposer', '/rover/', names)
    assert text.startswith('~actions is not set (looked for /rover/generic_decomposer/actions, found '
                           '/rover/generic_decomposer/generic_decomposer/actions): ')
    assert ('a file given as <rosparam command="load" file="FILE"/> inside the <node> element needs `actions:` '
            'at its top level: remove the `generic_decomposer:` line') in text


def test_a_top_level_file_loaded_into_the_namespace_says_so():
    names = loaded(TUTORIAL, '/rover/')
    assert layout.missing('perceptions', '/rover/generic_synthesizer', '/rover/', names) == (
        '~perceptions is not set (looked for /rover/generic_synthesizer/perceptions, found /rover/perceptions): '
        'a file with `perceptions:` at its top level was loaded into the namespace /rover/, not into this node: '
        'give it as robot.launch perceptions:=FILE, or wrap what it holds in `generic_synthesizer:`')


def test_wiring_under_another_node_name_is_pointed_at():
    names = loaded(PATROL, '/rover/')     # right place, but this node is named "synth"
    assert layout.missing('perceptions', '/rover/synth', '/rover/', names) == (
        '~perceptions is not set (looked for /rover/synth/perceptions; in the namespace only '
        '/rover/generic_synthesizer/perceptions): the wiring is there under another node\'s name: name this node '
        'generic_synthesizer, or the file\'s top-level key synth')


def test_nothing_anywhere_says_where_it_looked_and_how_to_give_one():
    assert layout.missing('perceptions', '/generic_synthesizer', '/', ['/run_id', '/rosdistro']) == (
        '~perceptions is not set (looked for /generic_synthesizer/perceptions and /perceptions): give this node a '
        'wiring file with `perceptions:` at its top level as robot.launch perceptions:=FILE')


class FakeServer(object):
    def __init__(self, params):
        self.params = params

    def has_param(self, name):
        return name.replace('~', '/rover/generic_synthesizer/') in self.params

    def get_param(self, name):
        return self.params[name.replace('~', '/rover/generic_synthesizer/')]

    def get_name(self):
        return '/rover/generic_synthesizer'

    def get_namespace(self):
        return '/rover/'

    def get_param_names(self):
        return list(self.params)


def test_wiring_param_returns_the_value_or_raises_the_explanation():
    assert layout.wiring_param('perceptions', FakeServer({'/rover/generic_synthesizer/perceptions': 1})) == 1
    with pytest.raises(ConfigError, match=r'^~perceptions is not set \(looked for '):
        layout.wiring_param('perceptions', FakeServer({}))
