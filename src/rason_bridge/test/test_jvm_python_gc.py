"""rason_mas's JVM and Python's collector (rason_bridge.jvm.start_jvm, in a process of its own):
the objects alive at start-up are out of the collections JPype runs at each JVM collection, and
garbage made later is still collected by them."""
import os
import subprocess
import sys

#: Prints the tracked objects a full collection walks and the frozen ones after start_jvm, then
#: whether a cycle made after it was freed by the Python collection a JVM collection triggers.
CHILD = '''
import gc, time, weakref, jpype
from rason_bridge import jvm, mas_node  # the node's imports: rospy, genpy, numpy
class Cycle(object):
    pass
before = Cycle()
jvm.start_jvm()
print(len(gc.get_objects()), gc.get_freeze_count(), any(o is before for o in gc.get_objects()))
made = Cycle()
made.self = made
alive = weakref.ref(made)
del made
jpype.JClass('java.lang.System').gc()
deadline = time.monotonic() + 20
while alive() is not None and time.monotonic() < deadline:
    time.sleep(0.01)
print(alive() is None)
'''


def test_start_up_objects_are_frozen_and_later_garbage_is_still_collected():
    env = dict(os.environ, RASON_JVM_OPTIONS='-XX:-ExplicitGCInvokesConcurrent')  # System.gc: a full collection
    done = subprocess.run([sys.executable, '-c', CHILD], env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=120)
    assert done.returncode == 0, done.stderr
    walked, frozen, before_walked, freed = done.stdout.split()
    assert int(frozen) > 20000, frozen
    assert int(walked) < int(frozen) // 10, (walked, frozen)
    assert before_walked == 'False'
    assert freed == 'True'
