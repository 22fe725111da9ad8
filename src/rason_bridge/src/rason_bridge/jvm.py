"""Starting the JVM that hosts Jason, once per process."""
import gc
import glob
import os

import jpype

from rason_bridge import cds

#: Debian's python3-jpype needs its support jar on the class path.
JPYPE_SUPPORT_JAR = '/usr/share/java/org.jpype.jar'

#: -Xrs: SIGINT/SIGTERM are rospy's. The G1 options give memory back after a burst: a flood
#: of perceptions allocates fast but keeps little alive (a few MB), and G1 grew its young
#: generation to most of a GB and kept it. Now it may spend more time collecting (GCTimeRatio
#: 4: up to 20 % instead of 8 %) before it grows the heap, and shrinks it to at most 30 % free
#: after a concurrent collection: one the node asks for when a flood ends (System.gc, made
#: concurrent), or one G1 makes after 30 s without any (an idle node; every 2 s cost a busy
#: one 4 % of a core).
JVM_OPTIONS = ('-Xrs', '-Djava.awt.headless=true', '-XX:+UseG1GC', '-XX:GCTimeRatio=4',
               '-XX:MinHeapFreeRatio=10', '-XX:MaxHeapFreeRatio=30', '-XX:+ExplicitGCInvokesConcurrent',
               '-XX:G1PeriodicGCInterval=30000')

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


def jvm_options():
    """The JVM's options: :data:`JVM_OPTIONS`, then ``RASON_JVM_OPTIONS`` (space-separated;
    a later option wins, e.g. ``-Xmx512m`` or ``-XX:G1PeriodicGCInterval=0``)."""
    return list(JVM_OPTIONS) + os.environ.get('RASON_JVM_OPTIONS', '').split()


def gc_options():
    """The options of :data:`JVM_OPTIONS` that choose and tune the collector (the class-data
    sharing archive is dumped with them)."""
    return [o for o in JVM_OPTIONS if o.startswith('-XX:')]


#: What :func:`start_jvm` decided about class-data sharing (one line for the node's log).
cds_decision = 'class-data sharing: the JVM has not been started here'


def start_jvm(classpath=None, cds_archive=None):
    """Start the JVM if this process has none yet; returns the class path in use.

    ``-Xrs`` leaves SIGINT/SIGTERM to rospy, so Ctrl-C stops the node cleanly. The class-data
    sharing archive made by ``make jason_lib`` (``cds_archive``: another one; ``False``: none) is
    mapped when it fits the class path and this JVM (:func:`rason_bridge.cds.decide`); a later
    ``RASON_JVM_OPTIONS`` ``-XX:SharedArchiveFile`` or ``-Xshare:off`` still wins. Jason's
    configuration is then completed as Jason's runner completes it (``RasonConfig.install``).
    """
    global cds_decision
    if jpype.isJVMStarted():
        return None
    cp = list(classpath or jason_lib_classpath())
    if os.path.isfile(JPYPE_SUPPORT_JAR):
        cp.append(JPYPE_SUPPORT_JAR)
    option, cds_decision = None, 'class-data sharing: not asked for'
    if cds_archive is not False:
        option, cds_decision = cds.decide(cds_archive or cds.archive_path(_WORKSPACE_ROOT), cp,
                                          jpype.getDefaultJVMPath())
    jpype.startJVM(*([option] if option else []) + jvm_options(), classpath=cp, convertStrings=False,
                   interrupt=False)
    if option and 'sharing' not in str(jpype.JClass('java.lang.System').getProperty('java.vm.info')):
        cds_decision = 'class-data sharing: off, the JVM did not map %s' % option.partition('=')[2]
    # Jason's configuration as Jason's runner makes it, before any Jason term: Jason reads some
    # of its settings (shortUnnamedVars) once, when its term classes are first used
    jpype.JClass('rason.infra.RasonConfig').install()
    settle_python_objects()
    return cp


def settle_python_objects():
    """Moves the Python objects alive now to the collector's permanent generation. JPype runs a full Python collection each time the
    JVM collects (its reference queue's sentinel is cleared): with the ~44,000 objects of rospy,
    genpy, numpy and JPype (modules, classes, functions: they live as long as the process)
    walked each time, that was 20-30 ms of CPU per young collection of the JVM, about a
    quarter of the node's CPU under a perception burst. Objects made later are collected as
    before. (No collection first: it would cost start-up as much again, for the little garbage
    there is at this point, kept now.)"""
    gc.freeze()
