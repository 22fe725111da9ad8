"""rason_mas's JVM (rason_bridge.jvm.start_jvm, one JVM per process, no ROS) with the class-data
sharing archive ``make jason_lib`` made, without it, and with a corrupt one: it starts and runs
Jason in each case, maps the archive only in the first, and says which in its line."""
import json
import os
import shutil
import subprocess
import sys

import pytest

from rason_bridge import cds, jvm

ARCHIVE = cds.archive_path(jvm._WORKSPACE_ROOT)

#: Starts the JVM with the archive argv[1] ('' for the default), makes a Bridge and prints the
#: decision line and java.vm.info.
CHILD = '''
import sys, jpype
from rason_bridge import jvm
jvm.start_jvm(cds_archive=sys.argv[1] or None)
jpype.JClass('rason.bridge.Bridge')()
print(jvm.cds_decision)
print(jpype.JClass('java.lang.System').getProperty('java.vm.info'))
'''


def start(archive, tmp_path):
    """(decision line, java.vm.info, the JVM's class-load log)."""
    loads = str(tmp_path / 'loads.txt')
    env = dict(os.environ, RASON_JVM_OPTIONS='-Xlog:class+load=info:file=' + loads)
    env.pop('RASON_CLASSPATH', None)
    env.pop('RASON_EXTRA_CLASSPATH', None)
    done = subprocess.run([sys.executable, '-c', CHILD, archive], env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stderr == ''  # a missing or refused archive is no error
    decision, info = done.stdout.splitlines()[-2:]
    with open(loads) as f:
        return decision, info, f.read()


def bridge_source(loads):
    return next(line for line in loads.splitlines() if ' rason.bridge.Bridge source: ' in line).split('source: ')[1]


@pytest.fixture
def copy(tmp_path):
    """A copy of the build's archive and its key."""
    if not os.path.isfile(ARCHIVE):
        pytest.fail('%s is missing: make jason_lib makes it' % ARCHIVE)
    path = str(tmp_path / cds.ARCHIVE_NAME)
    shutil.copy(ARCHIVE, path)
    shutil.copy(ARCHIVE + cds.KEY_SUFFIX, path + cds.KEY_SUFFIX)
    return path


def test_the_build_s_archive_is_mapped_and_jason_lib_s_classes_come_from_it(copy, tmp_path):
    decision, info, loads = start(copy, tmp_path)
    assert decision == 'class-data sharing: on (%s)' % copy
    assert 'sharing' in info
    assert bridge_source(loads) == 'shared objects file'


def test_without_the_archive_the_jvm_starts_with_the_jdk_s_own(tmp_path):
    missing = str(tmp_path / 'none.jsa')
    decision, info, loads = start(missing, tmp_path)
    assert decision.startswith('class-data sharing: no archive ' + missing)
    assert 'sharing' in info  # the JDK's archive still maps
    assert bridge_source(loads).endswith('rason-jason-lib.jar')


@pytest.mark.parametrize('damage', ['garbage', 'truncated'])
def test_a_corrupt_archive_is_refused_and_the_jvm_runs_without(copy, tmp_path, damage):
    with open(copy, 'rb') as f:
        head = f.read(4096)
    os.chmod(copy, 0o644)
    with open(copy, 'wb') as f:
        f.write(os.urandom(4096) if damage == 'garbage' else head)
    decision, _, loads = start(copy, tmp_path)
    assert decision == 'class-data sharing: off, the JVM did not map %s' % copy
    assert bridge_source(loads).endswith('rason-jason-lib.jar')


def test_a_stale_archive_is_not_given_to_the_jvm(copy, tmp_path):
    key = cds.read_key(copy)
    key['classpath'][0][2] -= 1  # made from an older jar
    with open(copy + cds.KEY_SUFFIX, 'w') as f:
        json.dump(key, f)
    decision, info, loads = start(copy, tmp_path)
    assert 'stale' in decision and 'sharing' in info
    assert bridge_source(loads).endswith('rason-jason-lib.jar')
