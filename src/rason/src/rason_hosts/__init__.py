"""rason_hosts: robots on network hosts of their own (Linux namespaces), shaped links, no rospy."""
from .hosts import Hosts, HostsError, Relay, cleanup, read_line, stop_process  # noqa: F401
