"""What the agents of the robots-on-hosts tests print (agents/hosts/peer.asl), read as it
arrives, and the checks made on it: each send received at most once, in order per sender,
ended in the sender, and delivered or failed with a documented reason, never lost silently.
Shared by the tests that run rason_mas processes in network namespaces (test_hosts_*.py)."""
import collections
import os
import re
import shutil
import subprocess
import threading
import time

import pytest

from rason_hosts import Hosts


def _workspace_built():
    return bool(shutil.which('rosrun')) and subprocess.run(
        ['rospack', 'find', 'rason_bridge'], capture_output=True).returncode == 0


#: The pytestmark of a test that runs rason_mas processes in network namespaces.
NEEDS_HOSTS_AND_WORKSPACE = [
    pytest.mark.skipif(os.geteuid() != 0, reason='network namespaces need root (CI runs as root)'),
    pytest.mark.skipif(not os.path.exists('/usr/sbin/nft'), reason='nftables not installed'),
    pytest.mark.skipif(not os.path.exists('/usr/sbin/mosquitto'), reason='mosquitto not installed'),
    pytest.mark.skipif(not shutil.which('roscore'), reason='ROS (roscore) not installed'),
    pytest.mark.skipif(not _workspace_built(), reason='needs the built catkin workspace (rason_bridge)'),
]

#: Failures a send made during the partition may end with (docs/guides/multi-robot.md): the
#: receiver already gone (receiver_not_found), or, with delivery receipts, no receipt within
#: message_ttl (undelivered) or the receiver left (receiver_departed).
ALLOWED_FAILURES = {'receiver_not_found', 'undelivered', 'receiver_departed'}

class Observed:
    """What the agents printed, parsed as it arrives (so waits check counters, not all lines)."""

    SEND = re.compile(r'^send (\d+) (tell|achieve|ask) (\d+)$')
    OUTCOME = re.compile(r'^(sent|answer|failed) (\d+)(?: (.*))?$')
    GOT = re.compile(r'^got (\w+) (\d+) (tell|achieve|ask)$')
    PRESENCE = re.compile(r'^(present|absent) (\w+) (\d+)$')
    DONE = re.compile(r'^(burst done|stream ended) (\d+)$')

    def __init__(self):
        self.sends = {}                           # (sender, n) -> (kind, sent at)
        self.order = collections.defaultdict(list)  # sender -> its numbers in sending order
        self.outcomes = collections.defaultdict(list)   # (sender, n) -> [(sent|answer|failed, detail)]
        self.got = collections.defaultdict(list)  # sender -> [(n, kind, printed at)] in order
        self.got_count = collections.Counter()    # (sender, n) -> receptions
        self.presence = []                        # (agent, peer, present?, agent's time)
        self.burst_done = {}
        self.stream_ended = {}
        self.other = []                           # agent lines none of the above

    def take(self, agent, text, arrived):
        m = self.SEND.match(text)
        if m:
            n = int(m.group(1))
            self.sends[(agent, n)] = (m.group(2), int(m.group(3)) / 1000.0)
            self.order[agent].append(n)
            return
        m = self.OUTCOME.match(text)
        if m:
            self.outcomes[(agent, int(m.group(2)))].append((m.group(1), m.group(3) or ''))
            return
        m = self.GOT.match(text)
        if m:
            sender, n = m.group(1), int(m.group(2))
            self.got[sender].append((n, m.group(3), arrived))
            self.got_count[(sender, n)] += 1
            return
        m = self.PRESENCE.match(text)
        if m:
            self.presence.append((agent, m.group(2), m.group(1) == 'present', int(m.group(3)) / 1000.0))
            return
        m = self.DONE.match(text)
        if m:
            (self.burst_done if m.group(1) == 'burst done' else self.stream_ended)[agent] = int(m.group(2))
            return
        self.other.append((agent, text))

    def failures(self, key):
        return [detail for what, detail in self.outcomes.get(key, ()) if what == 'failed']

    def resolved(self, key):
        """Ended in the sender, and for a tell or achieve not failed: also received."""
        if not self.outcomes.get(key):
            return False
        return self.sends[key][0] == 'ask' or bool(self.failures(key)) or self.got_count[key] > 0

    def unresolved(self):
        return [key for key in self.sends if not self.resolved(key)]

    def presence_changes(self, present, since):
        return [p for p in self.presence if p[2] == present and p[3] >= since]

    def resumed_since(self, sender, since):
        """A message sender sent at or after since has been received."""
        for n in reversed(self.order[sender]):
            if self.sends[(sender, n)][1] < since:
                return False
            if self.got_count[(sender, n)]:
                return True
        return False


class FleetLog:
    """Both rason_mas' output, each read by a thread of its own into one Observed."""

    AGENT_LINE = re.compile(r'\]: \[(\w+)\] (.*)$')

    def __init__(self):
        self.seen = Observed()
        self.raw = collections.defaultdict(list)
        self.ended = {}
        self._cond = threading.Condition()

    def follow(self, robot, proc):
        threading.Thread(target=self._read, args=(robot, proc), daemon=True).start()

    def _read(self, robot, proc):
        try:
            for line in iter(proc.stdout.readline, b''):
                arrived = time.time()
                text = line.decode(errors='replace').rstrip()
                with self._cond:
                    self.raw[robot].append('%.3f %s' % (arrived, text))
                    m = self.AGENT_LINE.search(text)
                    if m:
                        self.seen.take(m.group(1), m.group(2), arrived)
                    self._cond.notify_all()
        except (OSError, ValueError):   # the pipe closed when the hosts stopped it
            pass
        with self._cond:
            self.ended[robot] = proc.poll()
            self._cond.notify_all()

    def wait(self, predicate, timeout, what):
        """Until predicate(seen) holds; AssertionError naming what after timeout s or if a robot ended."""
        if not self.watch(predicate, timeout):
            raise AssertionError('%s: not within %g s%s\n%s' % (what, timeout, self._ended_text(),
                                                               self.tails()))

    def watch(self, predicate, seconds):
        """Whether predicate(seen) came to hold within seconds (False also when a robot ended)."""
        deadline = time.monotonic() + seconds
        with self._cond:
            while not predicate(self.seen):
                left = deadline - time.monotonic()
                if left <= 0 or self.ended:
                    return False
                self._cond.wait(left)
            return True

    def _ended_text(self):
        return ''.join('; %s ended (exit %s)' % item for item in sorted(self.ended.items()))

    def tails(self, count=25):
        with self._cond:
            return '\n'.join('--- %s:\n%s' % (robot, '\n'.join(lines[-count:]))
                             for robot, lines in sorted(self.raw.items()))

    def save(self, folder):
        with self._cond:
            for robot, lines in self.raw.items():
                with open(os.path.join(folder, '%s.log' % robot), 'w') as f:
                    f.write('\n'.join(lines) + '\n')


def drain(proc, path):
    """Copies what proc still prints to path, so its pipe never fills."""
    def copy():
        with open(path, 'ab') as f:
            try:
                while True:
                    data = os.read(proc.stdout.fileno(), 65536)
                    if not data:
                        return
                    f.write(data)
                    f.flush()
            except (OSError, ValueError):
                return
    threading.Thread(target=copy, daemon=True).start()



def check_sends(seen, keys, must_deliver, peer, message_ttl):
    """Problems with the sends keys ((sender, n)): each received at most once and ended in the
    sender; must_deliver: received exactly once and not failed; otherwise received or failed
    with an allowed reason, not both, and received within ~message_ttl."""
    problems = []
    arrival = {}
    for sender, lines in seen.got.items():
        for n, kind, at in lines:
            arrival.setdefault((sender, n), at)
    for key in sorted(keys):
        kind, sent_at = seen.sends[key]
        what = '%s -> %s #%d (%s, sent %.3f)' % (key[0], peer[key[0]], key[1], kind, sent_at)
        received, failures = seen.got_count[key], seen.failures(key)
        outcomes = seen.outcomes.get(key, [])
        if received > 1:
            problems.append('%s received %d times' % (what, received))
        if not outcomes:
            problems.append('%s never ended in the sender' % what)
        if must_deliver:
            if received == 0:
                problems.append('%s never received' % what)
            if failures:
                problems.append('%s failed: %s' % (what, failures))
        else:
            if received == 0 and not failures and kind != 'ask':
                problems.append('%s silently lost: neither received nor failed' % what)
            if received and failures and kind != 'ask':
                # an ask may end by its receiver's departure after it reached it
                problems.append('%s received and also failed in the sender (%s)' % (what, failures))
            for failure in failures:
                if failure not in ALLOWED_FAILURES:
                    problems.append('%s failed with %s, not one of %s' % (what, failure,
                                                                        sorted(ALLOWED_FAILURES)))
            if received and arrival[key] - sent_at > message_ttl + 1.0:
                problems.append('%s received %.1f s after it was sent (message_ttl %d s)'
                                % (what, arrival[key] - sent_at, message_ttl))
        for what_ended, detail in outcomes:
            if what_ended == 'answer' and detail != 'timeout' and not detail.startswith(
                    'val(%d,%d)' % (key[1], key[1])):
                problems.append('%s answered %s' % (what, detail))
    return problems


def check_order(seen, keys, peer):
    """Problems: a sender's messages among keys received out of its sending order."""
    problems = []
    wanted = set(keys)
    for sender in sorted(peer):
        numbers = [n for n, _, _ in seen.got[sender] if (sender, n) in wanted]
        for before, after in zip(numbers, numbers[1:]):
            if after <= before:
                problems.append('%s -> %s: #%d received after #%d' % (sender, peer[sender], after, before))
    return problems


def report(problems, limit=40):
    kinds = collections.Counter(re.sub(r'^\S+ -> \S+ #\d+ \(\w+, sent [\d.]+\) ', '', p)
                                for p in problems)
    return '%d problems (%s):\n%s' % (len(problems), '; '.join('%d x %s' % (n, k) for k, n in
                                                             kinds.most_common(8)),
                                      '\n'.join(problems[:limit]))


def stats(seen, keys):
    kinds = collections.Counter(seen.sends[k][0] for k in keys)
    received = sum(1 for k in keys if seen.got_count[k])
    failed = collections.Counter(f for k in keys for f in seen.failures(k))
    timeouts = sum(1 for k in keys for what, d in seen.outcomes.get(k, ()) if what == 'answer' and d == 'timeout')
    return 'sent %d (%s), received %d, failed %s, asks timed out %d' % (
        len(keys), ', '.join('%s %d' % kv for kv in sorted(kinds.items())), received,
        dict(failed) or 0, timeouts)


Run = collections.namedtuple('Run', 'seen marks folder')


def run_on_hosts(tmp_path_factory, name, host_names, play):
    """play(hosts, log, marks, folder) on Hosts(host_names), what the agents print read into a
    FleetLog and kept in a temporary folder named after name (also when play fails); returns
    the Run, having printed where the logs are and when each phase began (marks, wall clock)."""
    folder = str(tmp_path_factory.mktemp(name))
    log = FleetLog()
    marks = {'start': time.time()}
    try:
        with Hosts(host_names) as hosts:
            play(hosts, log, marks, folder)
            marks['end'] = time.time()
        marks['closed'] = time.time()
    finally:
        log.save(folder)
    print('\n%s: logs in %s; phases (s from start): %s' % (name, folder, ', '.join(
        '%s %.1f' % (k, v - marks['start']) for k, v in sorted(marks.items(), key=lambda kv: kv[1]))))
    return Run(log.seen, marks, folder)
