# pytest (make unit) collects only the unit tests of this folder: the test_*.py scripts
# that a .test file runs are rostest nodes that need a master, so they are left out here.
import glob
import os
import re


def _rostest_scripts(folder):
    names = set()
    for path in glob.glob(os.path.join(folder, '**', '*.test'), recursive=True):  # test/slow too
        with open(path) as f:
            names.update(re.findall(r'type="(test_[^"]+\.py)"', f.read()))
    return sorted(names)


collect_ignore = _rostest_scripts(os.path.dirname(os.path.abspath(__file__)))
