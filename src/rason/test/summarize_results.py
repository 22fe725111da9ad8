#!/usr/bin/python3
"""Print one 'N passed, N failed' line for the rostest results (JUnit XML) and set the exit code.

For each failed test it also prints why: the assertion message, then what its agents
printed and its nodes warned, from the run's ROS log folder (the rostest XML only holds
rostest's own lines), because CI keeps only the tail of the output.
"""
import glob
import os
import re
import sys
import xml.etree.ElementTree as ET

MESSAGE_CHARS = 1500
LOG_LINES = 40
# Launch output worth showing after a failure: agents' prints, rosout warnings and errors,
# Java and Python exceptions.
TELLING = re.compile(r'\[(faulty|helper|[a-z_]+)\] |WARN|ERROR|Exception|Error:|Traceback|FATAL')


def failures_of(suite):
    """(test name, message) of every failed or erroring test case in a <testsuite>."""
    found = []
    for case in suite.iter('testcase'):
        for bad in list(case.findall('failure')) + list(case.findall('error')):
            text = bad.get('message') or bad.text or ''
            found.append((case.get('name', '?'), text.strip()))
    return found


def test_name_of(result_file):
    """rosunit-case_x.xml -> case_x (the test-name of the rostest)."""
    name = os.path.basename(result_file)
    if name.startswith('rosunit-'):
        name = name[len('rosunit-'):]
    return name[:-len('.xml')] if name.endswith('.xml') else name


#: What the test-name of a multi-robot .test ends with when it runs with fleet_channel:=mqtt.
MQTT_SUFFIX = '_mqtt'


def launch_tail(results_dir, result_file):
    """The telling lines at the end of the launch output rostest stored for a test."""
    name = os.path.basename(result_file)
    if not name.startswith('rosunit-'):
        return []
    base = name[len('rosunit-'):]
    siblings = ['rostest-test_' + base]
    if base.endswith(MQTT_SUFFIX + '.xml'):
        # the .test run again with ARGS fleet_channel:=mqtt: catkin names its file by the args, without test_
        siblings.append('rostest-' + base[:-len(MQTT_SUFFIX + '.xml')] + '__fleet_channel_mqtt.xml')
    out = None
    for sibling in siblings:
        try:
            out = ET.parse(os.path.join(os.path.dirname(result_file), sibling)).getroot().findtext('system-out') or ''
            break
        except (OSError, ET.ParseError):
            continue
    if out is None:
        return []
    lines = [l for l in out.splitlines() if TELLING.search(l)]
    return lines[-LOG_LINES:]


# A line a node logged through rosout into its log file, e.g.
# "[rosout][INFO] 2026-11-24 10:26:50,644: [helper] My view of faulty did not settle".
ROSOUT_LINE = re.compile(r'^\[rosout\]\[(?P<level>[A-Z]+)\] (?P<time>\S+ \S+): (?P<text>.*)$')
AGENT_PRINT = re.compile(r'^\[[a-z][A-Za-z0-9_]*\] ')


def default_log_dir():
    """Where roslaunch puts its run folders: ROS_LOG_DIR, else ROS_HOME/log, else ~/.ros/log."""
    if os.environ.get('ROS_LOG_DIR'):
        return os.environ['ROS_LOG_DIR']
    return os.path.join(os.environ.get('ROS_HOME') or os.path.expanduser('~/.ros'), 'log')


def run_folder(log_dir, test_name):
    """The newest roslaunch run folder holding the log of the test node test_name, or None."""
    logs = glob.glob(os.path.join(glob.escape(log_dir), '*', glob.escape(test_name) + '-*.log'))
    if not logs:
        return None
    return os.path.dirname(max(logs, key=os.path.getmtime))


def run_log_tail(folder):
    """The agents' prints and every node's warnings and errors of one run, in time order,
    each with the node's log name ("helper-rason_mas-7"); the last LOG_LINES of them."""
    found = []
    for path in glob.glob(os.path.join(glob.escape(folder), '*.log')):
        node = os.path.basename(path)[:-len('.log')]
        if node.endswith('-stdout'):
            continue
        with open(path, errors='replace') as f:
            for line in f:
                m = ROSOUT_LINE.match(line.rstrip('\n'))
                if m and (m.group('level') in ('WARNING', 'WARN', 'ERROR', 'FATAL')
                          or AGENT_PRINT.match(m.group('text'))):
                    found.append((m.group('time'), '%s %s %s: %s' % (
                        m.group('time'), m.group('level'), node, m.group('text'))))
    found.sort(key=lambda item: item[0])
    return [text for _, text in found[-LOG_LINES:]]


def truncate(text, limit):
    return text if len(text) <= limit else text[:limit] + ' ... (%d more chars)' % (len(text) - limit)


def main(results_dir, log_dir=None):
    log_dir = log_dir or default_log_dir()
    files = sorted(glob.glob(os.path.join(results_dir, '**', '*.xml'), recursive=True))
    total = failed = 0
    broken = []
    summary = []
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
                rel = os.path.relpath(f, results_dir)
                summary.append('FAILED: %s (%d of %d)' % (rel, bad, n))
                print('---- %s' % rel)
                for case, message in failures_of(s):
                    print('%s: %s' % (case, truncate(message, MESSAGE_CHARS)))
                folder = run_folder(log_dir, test_name_of(f))
                tail = run_log_tail(folder) if folder else []
                if tail:
                    print('what its agents printed and its nodes warned (%s):' % folder)
                else:
                    tail = launch_tail(results_dir, f)
                    if tail:
                        print('last lines of its launch:')
                if tail:
                    print('\n'.join('  ' + l for l in tail))
    if not files:
        print('rostest: no result files in %s' % results_dir)
        return 1
    summary.extend('FAILED: unreadable result %s' % f for f in broken)
    print('\n'.join(summary))
    print('rostest: %d passed, %d failed' % (total - failed, failed + len(broken)))
    return 1 if failed or broken else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else 'build/test_results'))
