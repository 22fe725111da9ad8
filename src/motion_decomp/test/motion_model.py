"""The tests' own robot: a unicycle integrated here, optionally with the thesis's one-wheel
fault applied to the commands (Eq. 6.2/6.3, as the fault injector does), for the unit tests
of goto, arc and the scheduler (no ROS)."""
import math
from collections import namedtuple

DT = 0.02    # 50 Hz: robot.launch's control rate, the simulator's odometry rate


def healthy(v, w):
    return v, w


def one_wheel_fault(side):
    """The commands as a base with a faulty ``left`` or ``right`` actuator executes them: a
    forward or backward command turns by |linear x| (counter-clockwise for left), the
    commanded angular speed is lost and the linear speed halved; on the spot (x == 0) is
    unchanged. The robot drives arcs of curvature 2 rad/m."""
    sign = 1.0 if side == 'left' else -1.0

    def plant(v, w):
        if v == 0:
            return v, w
        return v / 2.0, sign * abs(v)
    return plant


def step(pose, v, w, dt=DT):
    """The pose after (v, w) for dt, exactly (an arc)."""
    x, y, yaw = pose
    if abs(w) < 1e-12:
        return (x + v * math.cos(yaw) * dt, y + v * math.sin(yaw) * dt, yaw)
    end = yaw + w * dt
    return (x + v / w * (math.sin(end) - math.sin(yaw)), y - v / w * (math.cos(end) - math.cos(yaw)),
            math.atan2(math.sin(end), math.cos(end)))


#: What a drive did: its result, when (s), the true end pose, the true path (poses), the
#: commands as sent (before the fault), and the number of turns on the spot begun.
Run = namedtuple('Run', 'result time pose path commands turns')


def drive(runner, start, plant=healthy, t=0.0, limit=120.0, lag=0, observe=None):
    """Run ``runner`` (``update(pose, now)``, ``command()``) on the model until it ends.

    :param plant: what the base does with a command (``healthy``, ``one_wheel_fault(side)``)
    :param lag: control cycles between a command and the wheels
    :param observe: ``observe(true_pose, now) -> pose or None``: what the runner is given
    """
    pose, path, commands, turns, turning = tuple(start), [tuple(start)], [], 0, False
    pending = [(0.0, 0.0)] * lag
    end = t + limit
    result = runner.update(observe(pose, t) if observe else pose, t)
    while result is None:
        if t > end:
            raise AssertionError('no result after %.0f s, at %r' % (limit, pose))
        command = runner.command()
        commands.append(command)
        now_turning = command[0] == 0 and command[1] != 0
        turns += now_turning and not turning
        turning = now_turning
        pending.append(command)
        pose = step(pose, *plant(*pending.pop(0)))
        path.append(pose)
        t += DT
        result = runner.update(observe(pose, t) if observe else pose, t)
    return Run(result, t, pose, path, commands, turns)


def off_line(path, start, goal):
    """The largest distance of the path from the straight line start -> goal (m)."""
    bx, by = goal[0] - start[0], goal[1] - start[1]
    length = math.hypot(bx, by)
    return max(abs((p[0] - start[0]) * by - (p[1] - start[1]) * bx) / length for p in path)


def path_length(path):
    return sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(path, path[1:]))
