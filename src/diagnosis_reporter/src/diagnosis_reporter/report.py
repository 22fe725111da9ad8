"""What the reporting actions mean, with no ROS: parsing their parameters and the fields of
the DiagnosticStatus that announces each (``rason/diagnosis``, ``rason/mission``)."""
import re

ACTION = 'report_diagnosis'
STATUS_NAME = 'rason/diagnosis'

# Component -> (level, sentence). Levels as diagnostic_msgs/DiagnosticStatus: 0 OK, 1 WARN, 2 ERROR.
COMPONENTS = {
    'none': (0, 'no fault'),
    'left_actuator': (1, 'fault in the left actuator'),
    'right_actuator': (1, 'fault in the right actuator'),
    'both_actuators': (1, 'fault in both actuators'),
    'odometry': (1, 'fault in the odometry system (encoders)'),
    'undiagnosed': (2, 'fault not diagnosed'),
}


class BadDiagnosis(ValueError):
    """The action's parameters are not a diagnosis (or not a mission report); the message
    says why."""


class Diagnosis(object):
    def __init__(self, agent, component, evidence):
        self.agent = agent
        self.component = component
        self.evidence = evidence

    @property
    def level(self):
        return COMPONENTS[self.component][0]

    @property
    def message(self):
        text = '%s: %s' % (self.agent, COMPONENTS[self.component][1])
        return '%s (%s)' % (text, self.evidence) if self.evidence else text

    def values(self):
        """Key/value pairs of the status, in a fixed order."""
        return [('agent', self.agent), ('component', self.component), ('evidence', self.evidence)]


def parse(agent, parameters):
    """report_diagnosis(Component) or report_diagnosis(Component, Evidence) -> Diagnosis."""
    if len(parameters) not in (1, 2):
        raise BadDiagnosis('report_diagnosis takes (Component) or (Component, Evidence), got %d '
                           'parameters' % len(parameters))
    component = parameters[0].strip()
    if component not in COMPONENTS:
        raise BadDiagnosis('unknown component %r; expected one of %s'
                           % (component, ', '.join(sorted(COMPONENTS))))
    evidence = parameters[1].strip() if len(parameters) == 2 else ''
    return Diagnosis(agent, component, evidence)


MISSION_ACTION = 'report_mission'
MISSION_STATUS_NAME = 'rason/mission'
#: How the mission went on after the diagnosis (issue 15: MAPE-K's Plan/Execute).
RECOVERIES = ('none', 'compensate', 'guided', 'delegate')
_AGENT_NAME = re.compile(r'[a-z][A-Za-z0-9_]*\Z')


def _names(text):
    # a Jason list of agent names as text: "[helper]", "[faulty,helper]", "[]"
    text = text.strip()
    if not (text.startswith('[') and text.endswith(']')):
        raise BadDiagnosis('By must be a list of agent names, e.g. [helper], got %r' % text)
    names = [n.strip() for n in text[1:-1].split(',') if n.strip()]
    bad = [n for n in names if not _AGENT_NAME.match(n)]
    if bad:
        raise BadDiagnosis('By must hold agent names, got %s' % ', '.join(map(repr, bad)))
    return names


class Mission(object):
    """A mission's outcome: completed or not, by which agents, with which recovery, after
    which diagnosis."""

    def __init__(self, agent, completed, by, recovery, diagnosis):
        self.agent = agent
        self.completed = completed
        self.by = by
        self.recovery = recovery
        self.diagnosis = diagnosis

    @property
    def level(self):
        return 0 if self.completed else 2

    @property
    def message(self):
        if not self.completed:
            return '%s: mission not completed (diagnosis %s, recovery %s)' % (
                self.agent, self.diagnosis, self.recovery)
        return '%s: mission completed by %s (diagnosis %s, recovery %s)' % (
            self.agent, ', '.join(self.by), self.diagnosis, self.recovery)

    def values(self):
        """Key/value pairs of the status, in a fixed order."""
        return [('agent', self.agent), ('completed', 'true' if self.completed else 'false'),
                ('by', ','.join(self.by)), ('recovery', self.recovery),
                ('diagnosis', self.diagnosis)]


def parse_mission(agent, parameters):
    """report_mission(Completed, By, Recovery, Diagnosis) -> Mission.

    Completed is ``true`` or ``false``, By a list of agent names (empty when not completed),
    Recovery one of :data:`RECOVERIES`, Diagnosis one of :data:`COMPONENTS`.
    """
    if len(parameters) != 4:
        raise BadDiagnosis('report_mission takes (Completed, By, Recovery, Diagnosis), got %d '
                           'parameters' % len(parameters))
    completed, by, recovery, diagnosis = (p.strip() for p in parameters)
    if completed not in ('true', 'false'):
        raise BadDiagnosis('Completed must be true or false, got %r' % completed)
    names = _names(by)
    if completed == 'true' and not names:
        raise BadDiagnosis('a completed mission names who completed it (By is empty)')
    if recovery not in RECOVERIES:
        raise BadDiagnosis('unknown recovery %r; expected one of %s'
                           % (recovery, ', '.join(RECOVERIES)))
    if diagnosis not in COMPONENTS:
        raise BadDiagnosis('unknown diagnosis %r; expected one of %s'
                           % (diagnosis, ', '.join(sorted(COMPONENTS))))
    return Mission(agent, completed == 'true', names, recovery, diagnosis)
