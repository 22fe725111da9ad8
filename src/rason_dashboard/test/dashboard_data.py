"""Messages and bags for the dashboard's tests: made here, as the robots would publish them."""
import math

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


#: The fleet bag's robots and their start poses (x, y, yaw): r1 ... r4 on a square.
FLEET_STARTS = {'r1': (2.0, 0.0, 3.1416), 'r2': (0.0, 2.0, -1.5708), 'r3': (-2.0, 0.0, 0.0),
                'r4': (0.0, -2.0, 1.5708)}
#: The contract net of the fleet bag, as (seconds after its start, sender, receiver, performative,
#: content): r4 calls r1, r2, r3 for an observation; r1 and r2 bid, r3 refuses; r4 awards r1,
#: which accepts; at the end r4 releases r1. r2's broadcast before it is the thesis's call.
FLEET_CONTRACT = 'contract(r4,1)'
FLEET_DIALOGUE = [
    (0.5, 'r2', '', 'achieve', 'helpme'),
    (1.0, 'r4', 'r1', 'achieve', 'callForBids(%s,observe(r4))' % FLEET_CONTRACT),
    (1.0, 'r4', 'r2', 'achieve', 'callForBids(%s,observe(r4))' % FLEET_CONTRACT),
    (1.0, 'r4', 'r3', 'achieve', 'callForBids(%s,observe(r4))' % FLEET_CONTRACT),
    (1.2, 'r1', 'r4', 'tell', 'propose(%s,2.1)' % FLEET_CONTRACT),
    (1.3, 'r2', 'r4', 'tell', 'propose(%s,3.5)' % FLEET_CONTRACT),
    (1.4, 'r3', 'r4', 'tell', 'refuse(%s)' % FLEET_CONTRACT),
    (2.5, 'r4', 'r1', 'achieve', 'award(%s,observe(r4))' % FLEET_CONTRACT),
    (2.6, 'r1', 'r4', 'tell', 'accepted(%s)' % FLEET_CONTRACT),
    (9.0, 'r4', 'r1', 'achieve', 'release(%s)' % FLEET_CONTRACT),
]


def pose_stamped(t, x, y, yaw):
    from geometry_msgs.msg import PoseStamped
    p = PoseStamped()
    p.header.stamp, p.header.frame_id = genpy.Time.from_sec(t), 'world'
    p.pose.position.x, p.pose.position.y = x, y
    p.pose.orientation.z, p.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return p


def odometry(t, robot, x, y, yaw):
    from nav_msgs.msg import Odometry
    o = Odometry()
    o.header.stamp, o.header.frame_id, o.child_frame_id = genpy.Time.from_sec(t), robot + '/odom', robot + '/base_footprint'
    o.pose.pose = pose_stamped(t, x, y, yaw).pose
    return o


def world_to_odom(robots):
    from geometry_msgs.msg import TransformStamped
    from tf2_msgs.msg import TFMessage
    tf = TFMessage()
    for robot, (x, y, yaw) in robots.items():
        t = TransformStamped()
        t.header.frame_id, t.child_frame_id = 'world', robot + '/odom'
        t.transform.translation.x, t.transform.translation.y = x, y
        t.transform.rotation.z, t.transform.rotation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        tf.transforms.append(t)
    return tf


def fleet_bag(path, t0=200.0, duration=10.0):
    """A short bag of a fleet of four robots, as fleet.launch with agents would record it:
    each robot's mind (an agent named as its robot, with an intention stack), the contract
    net of FLEET_DIALOGUE, the simulator's true poses and each robot's odometry at 10 Hz, and
    /tf_static. r1 drives 1 m towards r4 after it took the award; its odometry counts 10 %
    too far."""
    with rosbag.Bag(path, 'w') as bag:
        def put(topic, msg, t):
            bag.write(topic, msg, genpy.Time.from_sec(t0 + t))
        put('/tf_static', world_to_odom(FLEET_STARTS), 0.0)
        for robot in sorted(FLEET_STARTS):
            plans = {'r4': ['p2: +!contract(observer,observe(r4)) <- !callForProposals(observer,observe(r4),Cs)',
                            'p1: +!diagnose <- !contract(observer,observe(r4))'],
                     'r1': ['p7: +!carryOut(observe(r4),r4) <- goto(0,-1)', 'p6: +!work(Id,T,C) <- !carryOut(T,C)']}
            put('/%s/jason/mind' % robot, mind('/%s/rason_mas' % robot, t0 + 0.1, robot, ['free[source(self)]'],
                                                plans.get(robot, ())), 0.1)
        for t, sender, receiver, performative, content in FLEET_DIALOGUE:
            put('/rason/messages', message(sender, receiver, performative, content), t)
        for k in range(int(duration * 10) + 1):
            t = k / 10.0
            for robot, (x, y, yaw) in sorted(FLEET_STARTS.items()):
                moved = min(1.0, max(0.0, t - 3.0) / 4.0) if robot == 'r1' else 0.0  # 1 m along its heading
                put('/%s/true_pose' % robot, pose_stamped(t0 + t, x + moved * math.cos(yaw), y + moved * math.sin(yaw),
                                                           yaw), t)
                put('/%s/odom' % robot, odometry(t0 + t, robot, 1.1 * moved, 0.0, 0.0), t)
