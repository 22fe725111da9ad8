"""Launch mistakes that say so, before any node starts: an arg value the launch files refuse
(naming the valid ones, as roslaunch shows it), an arg the file does not declare (run_launch
refuses it), the effective configuration run_launch shows first, and the fatal line it repeats
last. The launch files are parsed as roslaunch parses them; no ROS master."""
import os

import pytest

roslaunch = pytest.importorskip('roslaunch')
pytest.importorskip('rospkg').RosPack().get_path('rason')   # $(find rason) must resolve
from rason_tools.launch_args import PACKAGE  # noqa: E402
from rason_tools.launch_config import line, node_line  # noqa: E402
import rosgraph.names as rosgraph_names  # noqa: E402
from rason_tools.run_launch import configuration, last_fatal_line, undeclared_args  # noqa: E402


def refusal(launch, *args):
    """The text roslaunch stops with for ``launch ARGS`` (as on screen: 'Invalid <arg> tag: ...')."""
    path = os.path.join(PACKAGE, 'launch', launch)
    with pytest.raises(roslaunch.RLException) as e:
        roslaunch.config.load_config_default([(path, list(args))], None, verbose=False)
    return str(e.value)


@pytest.mark.parametrize('launch, arg, says', [
    ('faulty_helper.launch', 'fault:=left',
     "'fault:=left is not a fault: none, left_actuator, right_actuator, both_actuators or odometry'"),
    ('faulty_helper.launch', 'rate:=fast', "'rate:=fast: the real-time factor is a number, 0 or more"),
    ('faulty_helper.launch', 'rate:=-1', "'rate:=-1: the real-time factor is a number, 0 or more"),
    ('faulty_helper.launch', 'severity:=2', "'severity:=2: a number in (0, 1] is needed"),
    ('faulty_helper.launch', 'interaction:=dark', "'interaction:=dark is not known: none, dim, moved_light, occlusion or box'"),
    ('faulty_helper.launch', 'lockstep:=maybe', "'lockstep:=maybe is not known: true, false or auto'"),
    ('faulty_helper.launch', 'fleet_auth:=on', "'fleet_auth:=on is not known: required or off'"),
    ('two_robots.launch', 'fault:=left', "'fault:=left is not a fault"),
    ('fault_tolerance.launch', 'rate:=fast', "'rate:=fast: the real-time factor"),
    ('robot.launch', 'fault_at:=soon', "'fault_at:=soon: a number of seconds, 0 or more"),
    ('robot.launch', 'output:=loud', "'output:=loud is not known: screen or log'"),
    ('sim_world.launch', 'rate:=fast', "'rate:=fast: the real-time factor"),
    ('sim_world.launch', 'robots:=2fast', "'robots:=2fast: one or more distinct robot names"),
    ('sim_world.launch', 'robots:=rover rover', "'robots:=rover rover: one or more distinct"),
    ('sim_world.launch', 'socket_dir:=links', "'socket_dir:=links: an absolute path, or default'"),
    ('sim_link.launch', 'socket:=rover.sock', "'socket:=rover.sock: an absolute path, or default'"),
    ('fleet_case_study.launch', 'helpers:=auction', "'helpers:=auction is not known: contract_net or broadcast'"),
    ('fleet_case_study.launch', 'helpers:=broadcast', "'helpers:=broadcast needs recovery:=true'"),
    ('fleet_case_study.launch', 'poses:=r9:1,1,1', "'poses:=r9:1,1,1: robot:x,y,yaw entries (numbers)"),
    ('fleet_case_study.launch', 'poses:=r1:1,x,1', "'poses:=r1:1,x,1: robot:x,y,yaw entries (numbers)"),
    ('fleet_case_study.launch', 'poses:=r1:1,1', "'poses:=r1:1,1: robot:x,y,yaw entries (numbers)"),
])
def test_a_bad_value_stops_the_launch_naming_the_valid_ones(launch, arg, says):
    args = [arg] + {'robot.launch': ['ns:=r1'], 'sim_link.launch': ['robot:=rover']}.get(launch, [])
    assert 'Invalid <arg> tag: ' + says in refusal(launch, *args)


def test_a_fault_without_the_fault_injector_is_refused():
    assert "'fault:=odometry needs the fault injector: leave fault_injector:=true'" in refusal(
        'robot.launch', 'ns:=r1', 'fault:=odometry', 'fault_injector:=false')


def test_good_values_pass():
    path = os.path.join(PACKAGE, 'launch', 'faulty_helper.launch')
    config = roslaunch.config.load_config_default(
        [(path, ['fault:=left_actuator', 'rate:=0', 'severity:=0.5', 'lockstep:=true', 'fleet_auth:=off'])], None,
        verbose=False)
    assert {n.namespace for n in config.nodes} >= {'/faulty/', '/helper/'}


def test_sim_world_links_each_robot_on_its_own_socket():
    path = os.path.join(PACKAGE, 'launch', 'sim_world.launch')
    config = roslaunch.config.load_config_default(
        [(path, ['robots:=helper faulty', 'socket_dir:=/tmp/links'])], None, verbose=False)
    links = sorted(n.namespace for n in config.nodes if n.type == 'sim_link')
    assert links == ['/faulty/', '/helper/']
    assert config.params['/helper/sim_link/socket'].value == '/tmp/links/helper.sock'
    assert config.params['/faulty/sim_link/side'].value == 'world'
    assert config.params['/use_sim_time'].value is True


def test_an_undeclared_arg_is_refused_naming_close_ones_or_all():
    declared = ['ns', 'fault', 'rate']
    assert undeclared_args(['ns:=a', 'fault:=none', '_x:=1'], declared) == []
    assert undeclared_args(['nss:=x'], declared) == [
        "nss:=x: the launch file has no argument 'nss' (roslaunch would ignore it): did you mean ns?"]
    assert undeclared_args(['robto:=helper'], declared) == [
        "robto:=helper: the launch file has no argument 'robto' (roslaunch would ignore it): "
        "its arguments: ns, fault, rate"]


def test_the_configuration_shows_namespaces_nodes_programs_and_wiring():
    nodes = [('/rover/', 'motion_decomp', 'motion_decomp_node', ''),
             ('/rover/', 'generic_synthesizer', 'generic_synthesizer', ''),
             ('/rover/', 'rason_mas', 'rason_mas', '/x/driver.mas2j'),
             ('/', 'rason_sim', 'rason_sim_node', '')]
    params = ['/rover/generic_synthesizer/perceptions/pose/topic', '/rover/generic_synthesizer/perceptions/pose/type',
              '/rover/generic_synthesizer/perceptions/battery/topic', '/rason_sim/seed']
    assert configuration(nodes, params) == [
        '  /: rason_sim',
        '  /rover/: motion_decomp; generic_synthesizer (perceptions: battery, pose); rason_mas (program /x/driver.mas2j)']


def test_the_fatal_line_is_found_in_a_rospy_log():
    log = ('[rosout][INFO] 2026-11-26 18:50:00,100: starting\n'
           '[rosout][FATAL] 2026-11-26 18:50:00,123: generic_synthesizer: bad configuration: ~perceptions: x\n'
           '[rospy.core][INFO] 2026-11-26 18:50:00,200: signal_shutdown [bad configuration]\n')
    assert last_fatal_line(log) == 'generic_synthesizer: bad configuration: ~perceptions: x'
    assert last_fatal_line('[rosout][INFO] 2026-11-26 18:50:00,100: fine\n') is None


def test_robot_launch_hands_the_expected_sources_to_rason_mas():
    path = os.path.join(PACKAGE, 'launch', 'robot.launch')
    config = roslaunch.config.load_config_default(
        [(path, ['ns:=r1', 'mas:=/x/a.mas2j', 'expected_sources:=battery, pose'])], None, verbose=False)
    assert config.params['/r1/rason_mas/expected_sources'].value == ['battery', 'pose']
    config = roslaunch.config.load_config_default([(path, ['ns:=r1', 'mas:=/x/a.mas2j'])], None, verbose=False)
    assert '/r1/rason_mas/expected_sources' not in config.params


def configuration_lines(launch, *args):
    """The lines the launch's launch_config nodes print first under plain roslaunch, in start order."""
    path = os.path.join(PACKAGE, 'launch', launch)
    config = roslaunch.config.load_config_default([(path, list(args))], None, verbose=False)
    return [node_line(n.args) for n in config.nodes if (n.package, n.type) == ('rason', 'launch_config')]


def test_plain_roslaunch_shows_the_effective_configuration_first():
    for launch in ('faulty_helper.launch', 'fault_tolerance.launch', 'demo.launch'):
        path = os.path.join(PACKAGE, 'launch', launch)
        first = roslaunch.config.load_config_default([(path, [])], None, verbose=False).nodes[0]
        assert (first.package, first.type) == ('rason', 'launch_config'), launch
    agents = os.path.join(PACKAGE, 'agents', 'case_study')
    world = pytest.importorskip('rospkg').RosPack().get_path('rason_sim') + '/config/two_robots.yaml'
    # fualt:= is misspelt: roslaunch ignores it, and the default fault shows
    assert configuration_lines('faulty_helper.launch', 'fualt:=left_actuator', 'rate:=2') == [
        '[configuration] sim.launch: world %s (robots helper, faulty), robots all, rate 2, seed 1, lockstep auto' % world,
        '[configuration] robot.launch: namespace /helper/, program %s/helper.mas2j, wiring %s/perceptions.yaml, '
        'fault none, camera true, profile sim, fleet ros' % (agents, agents),
        '[configuration] robot.launch: namespace /faulty/, program %s/faulty.mas2j, wiring none, '
        'fault both_actuators, camera false, profile sim, fleet ros' % agents]
    assert configuration_lines('fault_tolerance.launch', 'fault:=odometry')[2] == (
        '[configuration] robot.launch: namespace /faulty/, program %s/faulty_mission.mas2j, wiring %s/perceptions.yaml, '
        'fault odometry, camera false, profile sim, fleet ros' % (agents, agents))
    assert configuration_lines('robot.launch', 'ns:=r1') == [
        '[configuration] robot.launch: namespace /r1/, program none, wiring none, fault none, camera false, profile sim, fleet ros']
    assert configuration_lines('demo.launch') == [
        '[configuration] demo.launch: program %s/agents/demo/demo.mas2j, robot fake_robot' % PACKAGE]


def test_a_configuration_line_names_a_world_s_robots_or_that_it_cannot_be_read():
    assert line(['sim.launch', 'world=/nonexistent.yaml', 'rate=1', '__name:=c', '__log:=/x.log']) == (
        '[configuration] sim.launch: world /nonexistent.yaml (cannot be read), rate 1')
    assert line(['robot.launch', 'wiring=']) == '[configuration] robot.launch: wiring (empty)'


def remaps(config, node):
    """The remappings roslaunch gives ``node`` (its full name), resolved in its namespace."""
    found = [n for n in config.nodes if n.namespace + n.name == node]
    assert found, node
    return {rosgraph_names.ns_join(found[0].namespace, a): rosgraph_names.ns_join(found[0].namespace, b)
            for a, b in found[0].remap_args}


def test_the_turtlebot2_profile_wires_kobuki_node_s_and_the_openni_camera_s_names():
    path = os.path.join(PACKAGE, 'launch', 'robot.launch')
    config = roslaunch.config.load_config_default(
        [(path, ['ns:=tb', 'profile:=turtlebot2', 'camera:=true'])], None, verbose=False)
    injector = remaps(config, '/tb/fault_injector')
    assert injector['/tb/cmd_vel_out'] == '/tb/mobile_base/commands/velocity'
    assert injector['/tb/odom_in'] == '/tb/odom'
    assert remaps(config, '/tb/motion_decomp')['/tb/cmd_vel'] == '/tb/cmd_vel_mux'
    camera = remaps(config, '/tb/vision_synth')
    assert {camera['/tb/camera/rgb/image_raw'], camera['/tb/camera/rgb/camera_info'],
            camera['/tb/camera/depth_registered/image_raw']} == {
        '/tb/camera/rgb/image_raw', '/tb/camera/rgb/camera_info', '/tb/camera/depth_registered/image_raw'}
    # without the fault injector, the decomposer drives kobuki_node's topic itself
    config = roslaunch.config.load_config_default(
        [(path, ['ns:=tb', 'profile:=turtlebot2', 'fault_injector:=false'])], None, verbose=False)
    decomposer = remaps(config, '/tb/motion_decomp')
    assert decomposer['/tb/cmd_vel'] == '/tb/mobile_base/commands/velocity'
    assert decomposer['/tb/odom'] == '/tb/odom'
    assert "'profile:=kobuki is not known: sim or turtlebot2'" in refusal('robot.launch', 'ns:=tb', 'profile:=kobuki')


def test_fleet_start_poses_override_the_world_file_s_and_a_run_ends_and_records_when_asked():
    path = os.path.join(PACKAGE, 'launch', 'fleet_case_study.launch')
    config = roslaunch.config.load_config_default(
        [(path, ['recovery:=true', 'helpers:=broadcast', 'poses:=r1:2.2,-0.1,3.0 r4:-1.5,1.5,-0.8',
                 'end_when_done:=true', 'record:=true', 'bag:=/tmp/run.bag'])], None, verbose=False)
    params = {k: p.value for k, p in config.params.items()}
    assert (params['/rason_sim/r1/x'], params['/rason_sim/r1/y'], params['/rason_sim/r1/yaw']) == (2.2, -0.1, 3.0)
    assert params['/rason_sim/r2/x'] == 1.768              # fleet.yaml's, not overridden
    assert params['/rason_sim/r1/markers/left'] == 'red'   # the rest of r1 stays
    assert params['/missions_done/agents'] == 'r1_robot r2_robot r3_robot r4_robot'
    nodes = {n.name: n for n in config.nodes}
    assert nodes['missions_done'].required
    assert '/r4/true_pose' in nodes['recorder'].args and '/rason/messages' in nodes['recorder'].args
    mas = {n.args for n in config.nodes if n.name == 'rason_mas'}
    assert len(mas) == 1 and mas.pop().endswith('/agents/fleet/fleet_robot_mission_broadcast.mas2j')
