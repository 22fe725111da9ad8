"""The class path of a Jason project's own Java classes: its internal actions, belief bases,
agent and architecture classes, environment. No rospy, no Java.

Jason loads every class a project names with ``Class.forName`` from its own class loader, the
JVM's class path: so the project's classes must be on it when the JVM starts (JPype cannot add
to it later), and this is worked out before :func:`rason_bridge.jvm.start_jvm`.
"""
import glob
import os
import re

from rason_bridge.params import ParamError

#: Where a Jason project's compiled classes and jars are, beside its ``.mas2j``, when ``~classpath``
#: is not given: the output of the Gradle build Jason makes for a new project (``src/java``,
#: ``src/env`` -> ``build/classes/java/main``, ``src/resources`` -> ``build/resources/main``),
#: that of Jason's older Ant build (``bin/classes``), and the jars in ``lib/`` (both builds take
#: every one of them).
CONVENTIONAL = ('build/classes/java/main', 'build/resources/main', 'bin/classes', 'lib/*.jar')

#: A path that is a pattern, as glob reads it.
_PATTERN = re.compile(r'[*?[]')


def _resolved(folder, entry):
    path = os.path.expanduser(entry)
    return os.path.normpath(path if os.path.isabs(path) else os.path.join(folder, path))


def _expanded(path):
    """A path with ``*``, ``?`` or ``[`` in it: what it matches, in a stable order."""
    return sorted(glob.glob(path)) if _PATTERN.search(path) else [path]


def project_classpath(mas2j_path, given):
    """The class path entries of the project ``mas2j_path``: ``given`` (``~classpath``, relative
    paths taken from the ``.mas2j``'s folder), or when it is empty the :data:`CONVENTIONAL` places
    that exist there.

    :param given: the checked ``~classpath`` (a list of paths; empty: not given)
    :rtype: list of str (absolute paths)
    :raises ParamError: a given entry that does not exist or a pattern that matches nothing
        (a typo would otherwise surface only as a class not found)
    """
    folder = os.path.dirname(os.path.abspath(mas2j_path))
    if not given:
        return [p for entry in CONVENTIONAL for p in _expanded(_resolved(folder, entry)) if os.path.exists(p)]
    out = []
    for entry in given:
        found = [p for p in _expanded(_resolved(folder, entry)) if os.path.exists(p)]
        if not found:
            what = 'matches nothing' if _PATTERN.search(entry) else 'does not exist'
            raise ParamError('classpath: %s (%s) %s' % (entry, _resolved(folder, entry), what))
        out.extend(p for p in found if p not in out)
    return out
