"""The JVM's class path and options (rason_bridge.jvm), without starting a JVM: plug-in jars and
extra options are appended."""
import os

from rason_bridge import jvm
from rason_bridge.jvm import JVM_OPTIONS, jason_lib_classpath, jvm_options


def test_extra_classpath_is_appended_after_jason_lib(monkeypatch):
    monkeypatch.delenv('RASON_CLASSPATH', raising=False)
    monkeypatch.setenv('RASON_EXTRA_CLASSPATH', os.pathsep.join(['/opt/my/managers.jar', '', '/opt/ia.jar']))
    cp = jason_lib_classpath()
    assert cp[0].endswith('rason-jason-lib.jar')
    assert cp[-2:] == ['/opt/my/managers.jar', '/opt/ia.jar']


def test_extra_classpath_also_follows_an_override(monkeypatch):
    monkeypatch.setenv('RASON_CLASSPATH', '/a.jar')
    monkeypatch.setenv('RASON_EXTRA_CLASSPATH', '/b.jar')
    assert jason_lib_classpath() == ['/a.jar', '/b.jar']


def test_without_extra_nothing_is_added(monkeypatch):
    monkeypatch.setenv('RASON_CLASSPATH', '/a.jar')
    monkeypatch.delenv('RASON_EXTRA_CLASSPATH', raising=False)
    assert jason_lib_classpath() == ['/a.jar']


def test_jvm_options_keep_signals_for_rospy_and_take_extra_ones_last(monkeypatch):
    monkeypatch.setenv('RASON_JVM_OPTIONS', ' -Xmx512m  -XX:G1PeriodicGCInterval=0 ')
    assert jvm_options()[0] == '-Xrs' and '-XX:+ExplicitGCInvokesConcurrent' in jvm_options()
    assert jvm_options()[-2:] == ['-Xmx512m', '-XX:G1PeriodicGCInterval=0']
    monkeypatch.delenv('RASON_JVM_OPTIONS')
    assert jvm_options() == list(JVM_OPTIONS)


def test_the_archive_is_dumped_with_the_collector_options_of_rason_mas():
    assert jvm.gc_options() == [o for o in JVM_OPTIONS if o.startswith('-XX:')]
    assert '-Xrs' not in jvm.gc_options()
