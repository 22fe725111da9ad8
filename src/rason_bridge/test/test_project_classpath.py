"""The project's own class path: ~classpath resolved from the .mas2j's folder, else the
places Jason's project builds put classes and jars."""
import os

import pytest

from rason_bridge.params import ParamError, read_settings
from rason_bridge.project_classpath import project_classpath


def _project(tmp_path, *files):
    for f in files:
        path = tmp_path / f
        if f.endswith('/'):  # a folder
            path.mkdir(parents=True, exist_ok=True)
        else:
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text('')
    return str(tmp_path / 'p.mas2j')


def test_without_the_parameter_the_conventional_places_that_exist_are_taken_in_order(tmp_path):
    mas2j = _project(tmp_path, 'p.mas2j', 'lib/b.jar', 'lib/a.jar', 'lib/notes.txt', 'bin/classes/',
                     'build/classes/java/main/')
    assert project_classpath(mas2j, []) == [str(tmp_path / p) for p in (
        'build/classes/java/main', 'bin/classes', 'lib/a.jar', 'lib/b.jar')]


def test_a_project_with_none_of_them_has_no_classes_of_its_own(tmp_path):
    assert project_classpath(_project(tmp_path, 'p.mas2j', 'src/java/x.java'), []) == []


def test_given_entries_replace_the_conventional_places_and_relative_ones_are_from_the_project_folder(tmp_path):
    mas2j = _project(tmp_path, 'p.mas2j', 'lib/a.jar', 'out/', 'jars/x.jar', 'jars/y.jar')
    other = tmp_path / 'elsewhere'
    other.mkdir()
    assert project_classpath(mas2j, ['out', 'jars/*.jar', str(other), 'out']) == [
        str(tmp_path / 'out'), str(tmp_path / 'jars/x.jar'), str(tmp_path / 'jars/y.jar'), str(other)]


def test_a_relative_mas2j_path_is_taken_from_the_working_directory(tmp_path, monkeypatch):
    _project(tmp_path, 'p.mas2j', 'bin/classes/')
    monkeypatch.chdir(tmp_path)
    assert project_classpath('p.mas2j', []) == [str(tmp_path / 'bin/classes')]


@pytest.mark.parametrize('entry, what', [('nowhere', 'does not exist'), ('lib/*.jar', 'matches nothing')])
def test_a_given_entry_that_finds_nothing_is_refused_naming_it(tmp_path, entry, what):
    mas2j = _project(tmp_path, 'p.mas2j')
    with pytest.raises(ParamError) as e:
        project_classpath(mas2j, [entry])
    assert str(e.value) == 'classpath: %s (%s) %s' % (entry, tmp_path / entry, what)


@pytest.mark.parametrize('value, entries', [
    ([], []),
    (['a', ' b ', ''], ['a', 'b']),
    ('a%sb%s' % (os.pathsep, os.pathsep), ['a', 'b']),
    ('', []),
])
def test_the_parameter_is_a_list_or_one_path_separated_string(value, entries):
    assert read_settings(lambda n, d: value if n == 'classpath' else d, '/tmp').classpath == entries


@pytest.mark.parametrize('value', [3, ['a', 3], {'a': 'b'}, True])
def test_anything_else_is_a_bad_parameter(value):
    with pytest.raises(ParamError) as e:
        read_settings(lambda n, d: value if n == 'classpath' else d, '/tmp')
    assert str(e.value).startswith('classpath must be a list of paths, or one string of paths separated by')
