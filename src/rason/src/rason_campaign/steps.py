"""Step boundaries and outcome of one run, from the messages it recorded (no ROS).

A run is a time-ordered list of events ``(t, kind, fields)`` (``bagread`` makes them from a
bag; tests build them by hand), t in seconds of simulated time:

- ``('action', t, {'robot', 'agent', 'action', 'parameters'})`` from <robot>/jason/action
- ``('message', t, {'sender', 'receiver', 'performative', 'content'})`` from /rason/messages
- ``('diagnosis', t, {'agent', 'component', 'evidence'})`` from /diagnostics status
  ``rason/diagnosis``

Boundaries (thesis chapter 7): start = Faulty's first ``move`` action; help = Faulty's
broadcast (empty receiver) of ``helpme``; found = the helper's ``found(...)`` to Faulty;
diagnosis = the first diagnosis status. Steps: fault detection = help - start, robot
location = found - help, diagnosis = diagnosis - found, total = diagnosis - start.
"""
import bisect

FAULTY_ROBOT = 'faulty'
OUTCOMES = ('correct', 'undiagnosed', 'wrong')
STEP_NAMES = ('fault_detection', 'robot_location', 'diagnosis', 'total')


class Steps(object):
    """Boundary times (None when not reached) and the diagnosed component of a run."""

    def __init__(self, start=None, help=None, found=None, diagnosed=None, component=None,
                 evidence=''):
        self.start = start
        self.help = help
        self.found = found
        self.diagnosed = diagnosed
        self.component = component
        self.evidence = evidence

    @staticmethod
    def _span(a, b):
        return round(b - a, 3) if a is not None and b is not None else None

    def durations(self):
        """Step name -> seconds, None when a boundary is missing.

        :rtype: dict
        """
        return {'fault_detection': self._span(self.start, self.help),
                'robot_location': self._span(self.help, self.found),
                'diagnosis': self._span(self.found, self.diagnosed),
                'total': self._span(self.start, self.diagnosed)}

    def to_dict(self):
        return {'start': self.start, 'help': self.help, 'found': self.found,
                'diagnosed': self.diagnosed, 'component': self.component,
                'evidence': self.evidence}

    @classmethod
    def from_dict(cls, d):
        return cls(**d)


def extract_steps(events, faulty_robot=FAULTY_ROBOT):
    """The run's boundaries, each the first event that marks it (help only after start,
    found only after help, from the agent help was asked by).

    :param events: iterable of (t, kind, fields), in any order
    :rtype: Steps
    """
    steps = Steps()
    asker = None
    for t, kind, f in sorted(events, key=lambda e: e[0]):
        if kind == 'action' and steps.start is None:
            if f.get('robot') == faulty_robot and f.get('action') == 'move':
                steps.start = t
        elif kind == 'message' and steps.start is not None:
            if (steps.help is None and f.get('receiver') == '' and f.get('content') == 'helpme'
                    and f.get('performative') == 'achieve'):
                steps.help, asker = t, f.get('sender')
            elif (steps.help is not None and steps.found is None
                  and f.get('receiver') == asker and f.get('content', '').startswith('found(')):
                steps.found = t
        elif kind == 'diagnosis' and steps.diagnosed is None:
            steps.diagnosed = t
            steps.component = f.get('component')
            steps.evidence = f.get('evidence', '')
    return steps


def classify(fault, component):
    """Outcome of a run with ``fault`` injected whose diagnosis is ``component`` (None: no
    diagnosis at all).

    :rtype: str, one of OUTCOMES
    """
    if component is None or component == 'undiagnosed':
        return 'undiagnosed'
    return 'correct' if component == fault else 'wrong'


def judge(fault, steps, failure=None):
    """Outcome of a run and why, from its steps and, when the run itself went wrong, the
    runner's or the bag reader's ``failure`` text (a timeout, a crash, no bag).

    :rtype: (outcome, reason)
    """
    outcome = classify(fault, steps.component)
    if steps.component is None:
        return outcome, failure or 'no diagnosis recorded'
    if outcome != 'wrong':
        return outcome, steps.evidence or steps.component
    return outcome, ('%s: %s' % (steps.component, steps.evidence) if steps.evidence
                     else steps.component)


def clock_mapper(pairs, same_within=0.05):
    """A function from a bag's record time to simulated time, from the /clock messages
    ``(record time, clock value)``. rosbag records on simulated time under /use_sim_time,
    so when the two agree (median difference below ``same_within`` s) the record time is
    kept; otherwise (a recorder on wall time) a time maps to the clock value of the latest
    /clock recorded at or before it plus the record time since.

    :param pairs: list of (record_time, clock) in seconds; empty -> identity
    """
    pairs = sorted(pairs)
    diffs = sorted(abs(c - r) for r, c in pairs)
    if not pairs or diffs[len(diffs) // 2] < same_within:
        return lambda t: t
    times = [p[0] for p in pairs]

    def to_sim(t):
        i = max(bisect.bisect_right(times, t) - 1, 0)
        return pairs[i][1] + (t - times[i])
    return to_sim
