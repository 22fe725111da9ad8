"""Class-data sharing for rason_mas's JVM: an archive of the classes a MAS loads while it starts
and runs its first cycles (Jason's, jason_lib's and the JDK's, parsed and laid out once), made by
the build (``make jason_lib``) and mapped by every JVM that fits it. Start-up is shorter and the
mapped classes are shared between the processes of one machine.

The JVM refuses an archive made from other jars or by another JVM build, silently, and then
turns off the JDK's own archive too; so the archive is used only while its key (the jars' and
the JVM's paths, sizes and modification times) matches, and the build remakes it when not.
No rospy; :mod:`rason_bridge.cds_build` makes the archive.
"""
import json
import os

#: The archive and its key, beside the jar they are made from (``make clean`` removes them).
ARCHIVE_NAME = 'rason-jason-lib.jsa'
KEY_SUFFIX = '.key'


def archive_path(root):
    """Where ``make jason_lib`` puts the archive of the jars under ``root``."""
    return os.path.join(root, 'jason_lib', 'target', ARCHIVE_NAME)


def file_id(path):
    """``[path, size, mtime_ns]``, or ``[path, None, None]`` for a missing file."""
    try:
        st = os.stat(path)
    except OSError:
        return [path, None, None]
    return [path, st.st_size, st.st_mtime_ns]


def make_key(classpath, libjvm):
    """What an archive was made from: the JVM and the class path, in order."""
    return {'jvm': file_id(libjvm), 'classpath': [file_id(p) for p in classpath]}


def read_key(archive):
    """The key written beside ``archive``, or None if it is missing or unreadable."""
    try:
        with open(archive + KEY_SUFFIX) as f:
            key = json.load(f)
    except (OSError, ValueError):
        return None
    return key if isinstance(key, dict) and isinstance(key.get('classpath'), list) else None


def decide(archive, classpath, libjvm):
    """``(option, why)``: the JVM option that maps ``archive`` (None: start without it) and one
    line saying why. The archive's class path must lead ``classpath`` (the JVM's own rule; more
    jars may follow) with the same files, and the JVM must be the one that made it."""
    if not os.path.isfile(archive):
        return None, 'class-data sharing: no archive %s (make jason_lib makes it)' % archive
    key = read_key(archive)
    if key is None:
        return None, 'class-data sharing: %s has no readable key; rebuild it with make jason_lib' % archive
    made_from = [entry[0] for entry in key['classpath'] if entry]
    if list(classpath[:len(made_from)]) != made_from:
        return None, 'class-data sharing: off, the class path is not the one %s was made for' % archive
    if make_key(made_from, libjvm) != key:
        return None, 'class-data sharing: %s is stale (jars or Java changed); make jason_lib remakes it' % archive
    return '-XX:SharedArchiveFile=' + archive, 'class-data sharing: on (%s)' % archive


def java_home(libjvm):
    """The Java home of ``.../lib/server/libjvm.so``."""
    return os.path.dirname(os.path.dirname(os.path.dirname(libjvm)))
