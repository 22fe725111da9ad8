#!/usr/bin/python3
"""Print one 'N passed, N failed' line for the rostest results (JUnit XML) and set the exit code."""
import glob
import os
import sys
import xml.etree.ElementTree as ET


def main(results_dir):
    files = glob.glob(os.path.join(results_dir, '**', '*.xml'), recursive=True)
    total = failed = 0
    broken = []
    for f in files:
        try:
            root = ET.parse(f).getroot()
        except ET.ParseError:
            broken.append(f)
            continue
        suites = [root] if root.tag == 'testsuite' else root.findall('testsuite')
        for s in suites:
            n = int(s.get('tests', 0))
            bad = int(s.get('failures', 0)) + int(s.get('errors', 0))
            total += n
            failed += bad
            if bad or n == 0:
                print('FAILED: %s (%d of %d)' % (os.path.relpath(f, results_dir), bad, n))
    if not files:
        print('rostest: no result files in %s' % results_dir)
        return 1
    for f in broken:
        print('FAILED: unreadable result %s' % f)
    print('rostest: %d passed, %d failed' % (total - failed, failed + len(broken)))
    return 1 if failed or broken else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else 'build/test_results'))
