"""What a diagnosis action means, with no ROS: parsing its parameters and the fields of the
DiagnosticStatus that announces it."""

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
    """The action's parameters are not a diagnosis; the message says why."""


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
