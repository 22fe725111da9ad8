"""``rosrun rason_bridge fleet_key``: random keys, written mode 0600, never overwritten by accident."""
import os
import stat

import jpype
import pytest

from rason_bridge.fleet_key import KEY_BYTES, generate_key, main, write_key
from rason_bridge.jvm import start_jvm


def mode(path):
    return stat.S_IMODE(os.stat(path).st_mode)


def test_keys_are_random_hex_of_32_bytes():
    keys = {generate_key() for _ in range(100)}
    assert len(keys) == 100
    for k in keys:
        assert len(k) == 2 * KEY_BYTES
        int(k, 16)


def test_a_key_file_is_private_and_made_with_its_folders(tmp_path):
    path = tmp_path / 'ros' / 'rason' / 'fleet.key'
    write_key(str(path), 'a' * 64)
    assert mode(path) == 0o600
    assert mode(path.parent) == 0o700
    lines = path.read_text().splitlines()
    assert lines[-1] == 'a' * 64
    assert all(line.startswith('#') for line in lines[:-1])


def test_an_existing_file_is_kept_unless_forced(tmp_path):
    path = tmp_path / 'fleet.key'
    path.write_text('old\n')
    os.chmod(path, 0o644)
    with pytest.raises(FileExistsError):
        write_key(str(path), 'b' * 64)
    assert path.read_text() == 'old\n'
    write_key(str(path), 'b' * 64, force=True)
    assert path.read_text().splitlines()[-1] == 'b' * 64
    assert mode(path) == 0o600, 'forced: the looser mode is gone too'


def test_the_command_writes_the_default_file_once(tmp_path, capsys):
    assert main([], ros_home=str(tmp_path)) == 0
    path = tmp_path / 'rason' / 'fleet.key'
    key = path.read_text().splitlines()[-1]
    assert str(path) in capsys.readouterr().out
    assert main([], ros_home=str(tmp_path)) == 1
    assert 'exists; not overwritten' in capsys.readouterr().err
    assert path.read_text().splitlines()[-1] == key
    assert main([str(path), '--force']) == 0
    assert path.read_text().splitlines()[-1] != key


def test_print_writes_nothing(tmp_path, capsys):
    assert main(['--print', str(tmp_path / 'k')]) == 0
    assert len(capsys.readouterr().out.strip()) == 2 * KEY_BYTES
    assert not (tmp_path / 'k').exists()


def test_rason_mas_reads_what_the_tool_writes(tmp_path):
    path = tmp_path / 'fleet.key'
    key = generate_key()
    write_key(str(path), key)
    start_jvm()
    keys = jpype.JClass('rason.messaging.FleetKeys').load(jpype.JClass('java.nio.file.Paths').get(str(path)))
    assert [str(i) for i in keys.ids()] == [str(jpype.JClass('rason.messaging.FleetKeys').idOf(key.encode()))]
    assert jpype.JClass('rason.messaging.FleetKeys').tooOpen(jpype.JClass('java.nio.file.Paths').get(str(path))) is None
