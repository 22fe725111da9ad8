"""``rosrun rason_dashboard dashboard``: every robot's agents, live, in a web page;
``rosrun rason_dashboard dashboard --bag FILE [--bag FILE ...]``: the same page over a recorded
run, with a time slider (no ROS master needed, nothing published); one bag per robot's host
replays as one run.

Live ~params: ``bind`` (127.0.0.1), ``port`` (8642; 0 takes a free one), ``messages_topic``
(/rason/messages). Replay takes ``--bind`` and ``--port`` instead.
"""
import argparse
import sys

DEFAULT_BIND = '127.0.0.1'
DEFAULT_PORT = 8642


def replay(argv):
    p = argparse.ArgumentParser(prog='dashboard', description='replay a recorded run in the Rason dashboard')
    p.add_argument('--bag', required=True, action='append',
                   help='a bag recorded with jason/mind (e.g. faulty_helper.launch record:=true); '
                        'repeat it for the bags of one run recorded on several hosts')
    p.add_argument('--bind', default=DEFAULT_BIND, help='address to serve on (default %(default)s)')
    p.add_argument('--port', type=int, default=DEFAULT_PORT, help='port (default %(default)s; 0: a free one)')
    args = p.parse_args(argv)
    from rason_dashboard.replay import load_bags
    from rason_dashboard.server import DashboardServer
    bags = ' '.join(args.bag)
    try:
        timeline, counts = load_bags(args.bag)
    except Exception as e:  # rosbag's errors have no common base worth naming
        sys.exit('dashboard: cannot read %s: %s' % (bags, e))
    if not counts['minds']:
        print('dashboard: %s has no rason_msgs/MindState (record jason/mind to see the agents)' % bags,
              file=sys.stderr)
    try:
        server = DashboardServer(timeline, args.bind, args.port).start()
    except OSError as e:
        sys.exit('dashboard: cannot serve on %s:%d: %s' % (args.bind, args.port, e))
    print('dashboard: replaying %s (%d mind states, %d messages, %d statuses, %d poses) on %s'
          % (bags, counts['minds'], counts['messages'], counts['statuses'], counts['poses'], server.url),
          flush=True)
    try:
        server.wait()
    except KeyboardInterrupt:
        server.stop()


def live():
    import rason_rospy
    import rospy
    from rason_dashboard.live import LiveFeed
    from rason_dashboard.server import DashboardServer
    from rason_dashboard.timeline import Timeline
    rason_rospy.init_node('rason_dashboard')
    bind = str(rospy.get_param('~bind', DEFAULT_BIND))
    port = rospy.get_param('~port', DEFAULT_PORT)
    if isinstance(port, bool) or not isinstance(port, int) or not 0 <= port <= 65535:
        rospy.logfatal('bad parameter: port must be a whole number from 0 to 65535, not %r', port)
        return 1
    timeline = Timeline(mode='live')
    LiveFeed(timeline, str(rospy.get_param('~messages_topic', '/rason/messages')))
    try:
        server = DashboardServer(timeline, bind, port, log=rospy.logwarn).start()
    except OSError as e:
        rospy.logfatal('cannot serve on %s:%d: %s', bind, port, e)
        return 1
    if bind not in ('127.0.0.1', 'localhost', '::1'):
        rospy.logwarn('the dashboard is served on %s: anyone who reaches it sees the agents\' minds', bind)
    rospy.set_param('~url', server.url)
    rospy.loginfo('dashboard on %s', server.url)
    rospy.spin()
    server.stop()
    return 0


def main(argv=None):
    import rospy
    args = rospy.myargv(sys.argv if argv is None else argv)[1:]
    if args and args[0].startswith('--'):
        replay(args)
    else:
        sys.exit(live())
