"""When rason_mas maps the class-data sharing archive (rason_bridge.cds.decide), without a JVM:
only while it fits the jars and the JVM it was made from, as the JVM itself would refuse it
(and with it the JDK's own archive) without a word."""
import json
import os

import pytest

from rason_bridge import cds


@pytest.fixture
def made(tmp_path):
    """An archive with its key, made from two jars and a JVM under tmp_path."""
    jars = [str(tmp_path / 'rason-jason-lib.jar'), str(tmp_path / 'jason.jar')]
    libjvm = str(tmp_path / 'jdk' / 'lib' / 'server' / 'libjvm.so')
    os.makedirs(os.path.dirname(libjvm))
    for path in jars + [libjvm]:
        with open(path, 'wb') as f:
            f.write(b'x' * 10)
    archive = str(tmp_path / cds.ARCHIVE_NAME)
    with open(archive, 'wb') as f:
        f.write(b'archive')
    with open(archive + cds.KEY_SUFFIX, 'w') as f:
        json.dump(cds.make_key(jars, libjvm), f)
    return archive, jars, libjvm


def test_a_fitting_archive_is_mapped_and_more_jars_may_follow(made):
    archive, jars, libjvm = made
    option, why = cds.decide(archive, jars + ['/project/classes', '/usr/share/java/org.jpype.jar'], libjvm)
    assert option == '-XX:SharedArchiveFile=' + archive
    assert why == 'class-data sharing: on (%s)' % archive


def test_no_archive_no_option(made, tmp_path):
    _, jars, libjvm = made
    option, why = cds.decide(str(tmp_path / 'missing.jsa'), jars, libjvm)
    assert option is None and 'no archive' in why and 'make jason_lib' in why


@pytest.mark.parametrize('key_text', [None, '', 'not json', '[1, 2]', '{"jvm": []}'])
def test_a_missing_or_unreadable_key_means_no_option(made, key_text):
    archive, jars, libjvm = made
    os.remove(archive + cds.KEY_SUFFIX)
    if key_text is not None:
        with open(archive + cds.KEY_SUFFIX, 'w') as f:
            f.write(key_text)
    option, why = cds.decide(archive, jars, libjvm)
    assert option is None and 'no readable key' in why


def test_a_rebuilt_jar_makes_the_archive_stale(made):
    archive, jars, libjvm = made
    st = os.stat(jars[1])
    os.utime(jars[1], ns=(st.st_atime_ns, st.st_mtime_ns + 1000))
    option, why = cds.decide(archive, jars, libjvm)
    assert option is None and 'stale' in why


def test_a_jar_of_another_size_makes_the_archive_stale(made):
    archive, jars, libjvm = made
    st = os.stat(jars[0])
    with open(jars[0], 'ab') as f:
        f.write(b'y')
    os.utime(jars[0], ns=(st.st_atime_ns, st.st_mtime_ns))
    assert cds.decide(archive, jars, libjvm)[0] is None


def test_another_jvm_build_makes_the_archive_stale(made):
    archive, jars, libjvm = made
    with open(libjvm, 'ab') as f:
        f.write(b'upgraded')
    option, why = cds.decide(archive, jars, libjvm)
    assert option is None and 'Java changed' in why


@pytest.mark.parametrize('runtime', [lambda jars: jars[::-1], lambda jars: jars[:1], lambda jars: ['/a.jar'] + jars])
def test_a_class_path_not_led_by_the_archive_s_means_no_option(made, runtime):
    archive, jars, libjvm = made
    option, why = cds.decide(archive, runtime(jars), libjvm)
    assert option is None and 'not the one' in why


def test_a_missing_jar_makes_the_archive_stale(made):
    archive, jars, libjvm = made
    os.remove(jars[1])
    assert cds.decide(archive, jars, libjvm)[0] is None


def test_the_archive_sits_beside_the_jar_and_java_home_is_above_libjvm():
    assert cds.archive_path('/ws') == '/ws/jason_lib/target/rason-jason-lib.jsa'
    assert cds.java_home('/usr/lib/jvm/java-17/lib/server/libjvm.so') == '/usr/lib/jvm/java-17'
