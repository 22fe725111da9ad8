"""The Unix domain socket file joining the two sides (it crosses network namespaces)."""
import errno
import os
import socket
import stat

# sun_path holds 108 bytes with the terminating NUL.
MAX_PATH = 107


def default_path(robot, ros_home=None):
    """$ROS_HOME/rason/sim_link/<robot>.sock (ROS_HOME defaulting to ~/.ros)."""
    home = ros_home or os.environ.get('ROS_HOME') or os.path.join(os.path.expanduser('~'), '.ros')
    return os.path.join(home, 'rason', 'sim_link', '%s.sock' % robot)


def check_path(path):
    """A clear ValueError for a path a Unix socket cannot have."""
    if not path:
        raise ValueError('the socket path is empty')
    if len(os.fsencode(path)) > MAX_PATH:
        raise ValueError('socket path %s is %d bytes, a Unix socket path holds at most %d: '
                         'choose a shorter one (~socket)' % (path, len(os.fsencode(path)), MAX_PATH))


class Listener:
    """A listening socket and the file it is bound to."""

    def __init__(self, sock, path):
        self.sock, self.path = sock, path
        self._inode = os.stat(path).st_ino

    def close(self):
        """Closes the socket and removes its file unless another listener replaced it."""
        self.sock.close()
        try:
            if os.stat(self.path).st_ino == self._inode:
                os.unlink(self.path)
        except OSError:
            pass


def listen(path):
    """A Listener at path, the file mode 0600 in a directory made 0700 if missing.

    A socket file nobody answers on (left by a killed world side) is replaced; one a live
    world side listens on is an error.
    """
    check_path(path)
    directory = os.path.dirname(os.path.abspath(path))
    os.makedirs(directory, mode=0o700, exist_ok=True)
    if os.path.exists(path) or os.path.islink(path):
        if not _is_socket(path):
            raise ValueError('%s exists and is not a socket: not replacing it' % path)
        if _answers(path):
            raise ValueError('another sim link already listens on %s' % path)
        os.unlink(path)
    server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    old_umask = os.umask(0o177)
    try:
        server.bind(path)
    finally:
        os.umask(old_umask)
    os.chmod(path, 0o600)
    server.listen(1)
    return Listener(server, path)


def connect(path, timeout=2.0):
    """A connected socket, or None if nothing listens at path (yet)."""
    check_path(path)
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    sock.settimeout(timeout)
    try:
        sock.connect(path)
    except OSError as err:
        sock.close()
        if err.errno in (errno.ENOENT, errno.ECONNREFUSED, errno.EAGAIN) or \
                isinstance(err, socket.timeout):
            return None
        raise
    sock.settimeout(None)
    return sock


def _is_socket(path):
    try:
        return stat.S_ISSOCK(os.lstat(path).st_mode)
    except OSError:
        return False


def _answers(path):
    probe = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    probe.settimeout(1.0)
    try:
        probe.connect(path)
        return True
    except OSError:
        return False
    finally:
        probe.close()
