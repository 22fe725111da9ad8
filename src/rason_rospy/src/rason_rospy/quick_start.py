"""Starting a rospy node sooner, with the same outcome.

- ``rospy.init_node`` checks every 0.1 s whether the node is registered with the master, which
  takes a few milliseconds: most of that 0.1 s is waited for nothing. It is checked every
  :data:`REGISTRATION_POLL` instead.
- rosgraph looks for its logging configuration (``python_logging.conf``) in ROS_HOME/config,
  then /etc/ros, then the folder of the rosgraph package, which it finds by crawling the
  package path before it looks in either of the first two. Naming the file found in the first
  two in ``ROS_PYTHON_LOG_CONFIG_FILE`` skips the crawl; when neither has one, rosgraph
  searches as ever.
"""
import os
import time

import rospkg

#: Seconds between checks of the node's registration while ``rospy.init_node`` waits for it.
REGISTRATION_POLL = 0.005
LOG_CONFIG = 'ROS_PYTHON_LOG_CONFIG_FILE'


class PollingTime(object):
    """The ``time`` module as ``rospy.impl.init`` sees it: its sleeps last ``period`` at most."""

    def __init__(self, period, sleep=time.sleep):
        self.period = period
        self._sleep = sleep

    def sleep(self, seconds):
        self._sleep(min(seconds, self.period))

    def __getattr__(self, name):
        return getattr(time, name)


def poll_registration_every(period=REGISTRATION_POLL):
    """Make ``rospy.init_node`` check its registration every ``period`` seconds."""
    import rospy.impl.init as init
    init.time = PollingTime(period)


def logging_config(ros_home, etc_ros):
    """rosgraph's logging configuration file in ROS_HOME/config or /etc/ros, or None."""
    for folder in (os.path.join(ros_home, 'config'), etc_ros):
        for extension in ('conf', 'yaml'):
            path = os.path.join(folder, 'python_logging.' + extension)
            if os.path.isfile(path):
                return path
    return None


def name_logging_config(environ=os.environ):
    """Name rosgraph's logging configuration in ``environ`` when it is found without a crawl."""
    if environ.get(LOG_CONFIG):
        return
    found = logging_config(rospkg.get_ros_home(environ), rospkg.get_etc_ros_dir(environ))
    if found:
        environ[LOG_CONFIG] = found
