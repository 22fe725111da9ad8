"""Command line client: ``rosrun fault_injector inject FAULT``.

Calls the ``inject_fault`` service resolved in the caller's namespace, so
``ROS_NAMESPACE=/faulty rosrun fault_injector inject left_actuator`` (or
``... inject left_actuator __ns:=/faulty``) reaches ``/faulty/inject_fault``.
Prints the node's return message.

Exit status: 0 on success, 1 if the service is absent or the call fails,
2 if the fault is unknown (the node is still asked, and says so).
"""
import argparse
import sys
import time

import rosgraph
import rospy
from rason_msgs.srv import FaultInjector

from fault_injector import faults

EXIT_OK = 0
EXIT_NO_SERVICE = 1
EXIT_UNKNOWN_FAULT = 2


def wait_for_service(service, timeout):
    """Wait until the master knows ``service``.

    Not ``rospy.wait_for_service``: without ``init_node`` it raises a
    misleading "time is not initialized" when the master is down.

    :param service: resolved service name
    :param timeout: seconds to keep trying
    :return: None once the service is advertised, else why it is not
    """
    master = rosgraph.Master(rospy.get_name())
    deadline = time.monotonic() + timeout
    while True:
        try:
            master.lookupService(service)
            return None
        except rosgraph.MasterException:
            reason = 'not advertised (is fault_injector_node running in this namespace?)'
        except OSError as e:
            reason = 'master %s unreachable: %s' % (rosgraph.get_master_uri(), e)
        if time.monotonic() >= deadline:
            return reason
        time.sleep(0.2)


def main(argv=None):
    """Parse the command line, call the service and exit.

    :param argv: arguments without the program name; default ``sys.argv[1:]``
        with ROS remapping arguments (``name:=value``) removed
    """
    if argv is None:
        argv = rospy.myargv(sys.argv)[1:]
    parser = argparse.ArgumentParser(
        prog='inject', description='Inject a fault into a fault_injector node, or cancel it.')
    parser.add_argument('fault', help='one of: %s' % faults.valid_requests_text())
    parser.add_argument('--service', default='inject_fault',
                        help='service name, resolved in ROS_NAMESPACE (default: %(default)s)')
    parser.add_argument('--timeout', type=float, default=5.0,
                        help='seconds to wait for the service (default: %(default)s)')
    args = parser.parse_args(argv)

    # No init_node: a plain service call needs no node, and resolve_name
    # already honours ROS_NAMESPACE and __ns:=.
    service = rospy.resolve_name(args.service)
    reason = wait_for_service(service, args.timeout)
    if reason:
        sys.stderr.write('inject: service %s not available after %g s: %s\n'
                         % (service, args.timeout, reason))
        sys.exit(EXIT_NO_SERVICE)
    try:
        response = rospy.ServiceProxy(service, FaultInjector)(args.fault)
    except (rospy.ServiceException, rospy.ROSException) as e:
        sys.stderr.write('inject: call to %s failed: %s\n' % (service, e))
        sys.exit(EXIT_NO_SERVICE)
    print(response.return_message)
    try:
        faults.parse_fault(args.fault)
    except faults.UnknownFaultError:
        sys.exit(EXIT_UNKNOWN_FAULT)
    sys.exit(EXIT_OK)
