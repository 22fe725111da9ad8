"""The JVM's class path (rason_bridge.jvm), without starting a JVM: plug-in jars are appended."""
import os

from rason_bridge.jvm import jason_lib_classpath


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
