"""How rason_mas ends when rospy shuts it down (no rospy here)."""

#: What rosmaster says when it tells a node that another one registered its name.
NAME_TAKEN = 'new node registered with same name'


def exit_for_shutdown(reason):
    """The exit status a shutdown for ``reason`` calls for, and the fatal line to log (or '').

    A node whose name another node took has not ended as asked: two nodes cannot
    share a name on one master, so the older is told to go by the master.

    :returns: ``(status, message)``; ``(0, '')`` for an ordinary shutdown
    """
    if reason and NAME_TAKEN in reason:
        return 1, ('another node registered with this node\'s name, so the master shut this one down; '
                   'give each rason_mas its own name or namespace (%s)' % reason)
    return 0, ''
