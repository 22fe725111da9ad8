"""Starting the JVM that hosts Jason, once per process."""
import glob
import os

import jpype

#: Debian's python3-jpype needs its support jar on the class path.
JPYPE_SUPPORT_JAR = '/usr/share/java/org.jpype.jar'

_WORKSPACE_ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..', '..', '..'))


class JvmError(RuntimeError):
    """The JVM cannot be started: missing jars or Java."""


def jason_lib_classpath(root=_WORKSPACE_ROOT):
    """The jars of jason_lib (built by ``make setup``) and their dependencies.

    ``RASON_CLASSPATH`` (path-separated jars) replaces the default;
    ``RASON_EXTRA_CLASSPATH`` is appended to it (e.g. a jar with your own
    perception manager or internal actions).

    :rtype: list of str
    :raises JvmError: when jason_lib has not been built
    """
    extra = [p for p in os.environ.get('RASON_EXTRA_CLASSPATH', '').split(os.pathsep) if p]
    override = os.environ.get('RASON_CLASSPATH')
    if override:
        return [p for p in override.split(os.pathsep) if p] + extra
    target = os.path.join(root, 'jason_lib', 'target')
    jar = os.path.join(target, 'rason-jason-lib.jar')
    if not os.path.isfile(jar):
        raise JvmError('%s not found: build jason_lib with `make setup` '
                       '(or set RASON_CLASSPATH)' % jar)
    return [jar] + sorted(glob.glob(os.path.join(target, 'lib', '*.jar'))) + extra


def start_jvm(classpath=None):
    """Start the JVM if this process has none yet; returns the class path in use.

    ``-Xrs`` leaves SIGINT/SIGTERM to rospy, so Ctrl-C stops the node cleanly.
    """
    if jpype.isJVMStarted():
        return None
    cp = list(classpath or jason_lib_classpath())
    if os.path.isfile(JPYPE_SUPPORT_JAR):
        cp.append(JPYPE_SUPPORT_JAR)
    jpype.startJVM('-Xrs', '-Djava.awt.headless=true', classpath=cp,
                   convertStrings=False, interrupt=False)
    return cp
