"""``python3 -m rason_bridge.cds_build ROOT`` (run by ``make jason_lib``): makes the class-data
sharing archive of the jars under ROOT (:mod:`rason_bridge.cds`) if it is missing or stale.

The class list comes from a run of a small project (``src/rason_bridge/cds_warmup``) in a JVM
started as rason_mas starts it, without ROS; the JDK's ``java -Xshare:dump`` then makes the
archive from it, with the collector options of rason_mas (the archive records them).
"""
import json
import os
import subprocess
import sys
import tempfile
import time

import jpype

from rason_bridge import java_config, jvm, log_pump
from rason_bridge.cds import ARCHIVE_NAME, KEY_SUFFIX, archive_path, decide, java_home, make_key
from rason_bridge.params import read_settings

#: The project whose start-up and first cycles fill the class list (under the workspace root).
WARMUP_MAS2J = os.path.join('src', 'rason_bridge', 'cds_warmup', 'warmup.mas2j')
#: What the warm-up agent prints when it has done everything it does.
WARMUP_DONE = 'cds warm-up done'


def _record(root, class_list):
    """In a process of its own: load and run the warm-up project as rason_mas would, with the
    JVM writing the name of every class it loads to ``class_list``."""
    os.environ['RASON_JVM_OPTIONS'] = '-XX:DumpLoadedClassList=' + class_list
    jvm.start_jvm(cds_archive=False)
    settings = read_settings(lambda name, default: default, tempfile.gettempdir())
    bridge = java_config.bridge()
    java_config.push(bridge, settings, '/cds_warmup', time.time_ns())
    bridge.attach()
    mas = java_config.load_mas(bridge, settings, os.path.join(root, WARMUP_MAS2J))
    bridge.tick(time.monotonic_ns())
    mas.start()
    bridge.perception().perceive('cds_warmup', ['seen(1)', 'pose(1.5, -2, "map")'], time.monotonic_ns())
    deadline = time.monotonic() + 60.0
    while time.monotonic() < deadline:
        lines = log_pump.batch_lines(bridge.log().drainBatch(log_pump.BATCH))
        if any(WARMUP_DONE in text for _, text in lines):
            os._exit(0)  # the class list is written as classes load
        time.sleep(0.05)
        bridge.tick(time.monotonic_ns())
    print('the warm-up agent did not finish within 60 s', file=sys.stderr)
    os._exit(1)


def build(root, log=print):
    """Make the archive of the jars under ``root`` unless an up-to-date one is there; returns
    the decision line for the archive now.

    :raises RuntimeError: a step failed (its output is in the message)
    """
    classpath = jvm.jason_lib_classpath(root)
    libjvm = jpype.getDefaultJVMPath()
    archive = archive_path(root)
    option, why = decide(archive, classpath, libjvm)
    if option:
        return why
    with tempfile.TemporaryDirectory() as tmp:
        class_list = os.path.join(tmp, 'classes.lst')
        env = dict(os.environ, RASON_CLASSPATH=os.pathsep.join(classpath), RASON_EXTRA_CLASSPATH='')
        _run([sys.executable, '-m', 'rason_bridge.cds_build', '--record', root, class_list], env, 'recording the class list')
        made = os.path.join(tmp, ARCHIVE_NAME)
        _run([os.path.join(java_home(libjvm), 'bin', 'java'), '-Xshare:dump', '-XX:SharedClassListFile=' + class_list,
              '-XX:SharedArchiveFile=' + made, '-cp', os.pathsep.join(classpath)] + jvm.gc_options(),
             os.environ, 'dumping the archive')
        with open(made + KEY_SUFFIX, 'w') as f:
            json.dump(make_key(classpath, libjvm), f)
        os.replace(made, archive)
        os.replace(made + KEY_SUFFIX, archive + KEY_SUFFIX)
    option, why = decide(archive, classpath, libjvm)
    if not option:
        raise RuntimeError('the archive just made does not fit: ' + why)
    log('made %s (%d MB)' % (archive, os.path.getsize(archive) // 2 ** 20))
    return why


def _run(argv, env, what):
    done = subprocess.run(argv, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=300)
    if done.returncode != 0:
        raise RuntimeError('%s failed (exit %d):\n%s' % (what, done.returncode, done.stdout[-4000:]))


def main(argv):
    if len(argv) == 3 and argv[0] == '--record':
        _record(argv[1], argv[2])
    if len(argv) != 1:
        print('usage: python3 -m rason_bridge.cds_build ROOT', file=sys.stderr)
        return 2
    try:
        print(build(os.path.abspath(argv[0])))
    except RuntimeError as e:
        print('class-data sharing archive: %s' % e, file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
