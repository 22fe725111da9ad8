"""Messages and bags for the dashboard's tests: made here, as the robots would publish them."""
import genpy
import rosbag
from std_msgs.msg import String
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus, KeyValue
from rason_msgs.msg import AgentMessage, AgentMind, IntentionState, MindState, PendingAction


#: A rule of the helper's belief base (rason_mas sends rules apart from beliefs).
NEAR_RULE = 'near(R) :- (robot(R,D) & (D < 1))'


def mind(mas_id, stamp, name, beliefs, intention_plans=(), action=None, rules=()):
    agent = AgentMind(name=name, cycle=int(stamp * 10), stamp=genpy.Time.from_sec(stamp), beliefs=list(beliefs),
                      rules=list(rules))
    if intention_plans:
        agent.intentions = [IntentionState(id=1, state='waiting', plans=list(intention_plans))]
        agent.goals = ['!helpme[source(faulty)]']
    if action:
        agent.actions = [PendingAction(id=7, action=action, started=genpy.Time.from_sec(stamp - 0.5), held=False)]
    return MindState(stamp=genpy.Time.from_sec(stamp), mas_id=mas_id, agents=[agent])


def message(sender, receiver, performative, content):
    return AgentMessage(sender_mas='/%s/rason_mas' % sender, sender=sender, receiver=receiver,
                        performative=performative, content=content)


def diagnosis(component, level=1):
    return DiagnosticArray(status=[
        DiagnosticStatus(level=level, name='rason/diagnosis', message='faulty: %s' % component,
                         values=[KeyValue('component', component)]),
        DiagnosticStatus(level=0, name='other/node', message='ignored')])


def case_study_bag(path, t0=100.0):
    """A short bag like a case-study run's: the helper's mind before and after it found
    Faulty, Faulty's, the dialogue, and the diagnosis at the end."""
    with rosbag.Bag(path, 'w') as bag:
        def put(topic, msg, t):
            bag.write(topic, msg, genpy.Time.from_sec(t))
        faulty = mind('/faulty/rason_mas', t0, 'faulty', ['stuck[source(self)]'])
        faulty.inspector_url = 'http://127.0.0.1:40001'  # Jason's mind inspector of that process
        put('/faulty/jason/mind', faulty, t0)
        put('/helper/jason/mind', mind('/helper/rason_mas', t0 + 0.1, 'helper', ['searching[source(self)]'],
                                       ['p1: +!findRobot(faulty) <- turn(10)'], 'turn(10)', [NEAR_RULE]), t0 + 0.1)
        put('/rason/messages', message('faulty', '', 'achieve', 'helpme'), t0 + 1)
        put('/helper/jason/mind', mind('/helper/rason_mas', t0 + 5, 'helper', ['found(faulty)[source(self)]'],
                                       rules=[NEAR_RULE]), t0 + 5)
        put('/rason/messages', message('helper', 'faulty', 'tell', 'found(faulty)'), t0 + 5.1)
        put('/diagnostics', diagnosis('both_actuators'), t0 + 9)
        put('/rosout_like', String(data='of no interest'), t0 + 9.5)  # a type the dashboard does not show
