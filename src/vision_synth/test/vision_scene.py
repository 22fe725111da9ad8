"""A tiny ray caster for the tests: a Kinect-like view of the faulty robot's cylinders.

Renders an RGB image and an organized xyz cloud (optical frame: x right, y down, z forward)
of a scene made of a floor, a back wall, the robot's base and its two vertical cylinders
(green on the robot's LEFT, orange on its RIGHT, 0.227 m apart) and, if asked for, a blue
third one 0.12 m behind their middle, plus optional grey posts that can hide things. Lambertian shading; ``light`` scales all lighting (0.3 = dimmed).

Ground truth uses the same conventions as vision_synth.geometry but is computed here from
the scene, independently: the robot at bearing ``angle`` (deg, + right), optical-axis
``depth`` (m) and heading ``heading`` (deg, clockwise from the camera's forward direction).
"""
import math

import numpy as np

WIDTH, HEIGHT = 640, 480
FX = FY = (WIDTH / 2.0) / math.tan(math.radians(57.0) / 2.0)  # 589.4 px
CX, CY = (WIDTH - 1) / 2.0, (HEIGHT - 1) / 2.0

CAMERA_HEIGHT = 0.30      # m above the floor
WALL_DEPTH = 4.5          # m
SEPARATION = 0.227        # m between the cylinder axes
BACK_OFFSET = 0.12        # m, the third (blue) cylinder behind the middle of the two
CYLINDER_RADIUS = 0.02    # m
CYLINDER_SPAN = (0.12, 0.45)  # m above the floor
BASE_RADIUS = 0.177
BASE_SPAN = (0.01, 0.11)

GREEN = (0.05, 0.65, 0.15)
ORANGE = (1.0, 0.45, 0.0)
BLUE = (0.1, 0.3, 0.95)
WALL_GREY = (0.6, 0.6, 0.6)
FLOOR_GREY = (0.45, 0.45, 0.45)
BASE_GREY = (0.2, 0.2, 0.2)
POST_GREY = (0.5, 0.5, 0.5)

# Direction from a surface towards the light: above, a little left, towards the camera.
LIGHT = np.array([-0.4, -0.7, -0.6]) / np.linalg.norm([-0.4, -0.7, -0.6])
AMBIENT = 0.3


def _shade(albedo, normal, light=LIGHT):
    """Lambertian colour (0..1) of ``albedo`` lit from direction ``light``, unit normal(s)."""
    lit = AMBIENT + (1.0 - AMBIENT) * np.clip(np.asarray(normal) @ light, 0.0, 1.0)
    return np.asarray(albedo) * np.asarray(lit)[..., None]


class Intrinsics(object):
    def __init__(self, fx=FX, fy=FY, cx=CX, cy=CY):
        self.fx, self.fy, self.cx, self.cy = fx, fy, cx, cy


def robot_centre(angle, depth):
    """(x, z) of a robot at bearing ``angle`` (deg) and optical-axis depth ``depth`` (m)."""
    return depth * math.tan(math.radians(angle)), depth


def cylinder_centres(x, z, heading, separation=SEPARATION):
    """(left, right) cylinder axis positions (x, z) of a robot at (x, z) facing ``heading``.

    Forward is bearing ``heading`` (clockwise from +z): ``(sin h, cos h)``; the right-hand
    side is 90° further clockwise: ``(cos h, −sin h)``.
    """
    h = math.radians(heading)
    rx, rz = math.cos(h), -math.sin(h)
    half = separation / 2.0
    return (x - half * rx, z - half * rz), (x + half * rx, z + half * rz)


def back_centre(x, z, heading, offset=BACK_OFFSET):
    """(x, z) of the third cylinder's axis: ``offset`` behind a robot at (x, z) facing
    ``heading`` (forward is ``(sin h, cos h)``)."""
    h = math.radians(heading)
    return x - offset * math.sin(h), z - offset * math.cos(h)


def _window(k, width, height, ox, oz, r, h0, h1):
    """Image rows/columns (slices) that a vertical cylinder in front of the camera can
    cover, a little generously; None when it is behind the camera."""
    near = oz - r
    if near <= 0.01:
        return (slice(None), slice(None)) if oz + r > 0 else None
    us = [k.cx + k.fx * (ox + dx) / z for dx in (-r, r) for z in (near, oz + r)]
    vs = [k.cy + k.fy * (CAMERA_HEIGHT - h) / z for h in (h0, h1) for z in (near, oz + r)]
    u0, u1 = max(int(min(us)) - 2, 0), min(int(max(us)) + 3, width)
    v0, v1 = max(int(min(vs)) - 2, 0), min(int(max(vs)) + 3, height)
    if u0 >= u1 or v0 >= v1:
        return None
    return slice(v0, v1), slice(u0, u1)


class Scene(object):
    """What the camera sees; build it, then :meth:`render`.

    :param robot: (angle, depth, heading) of the faulty robot, or None
    :param show: which cylinders exist: subset of {'left', 'right', 'back'}
    :param posts: grey vertical posts (x, z, radius), floor to 1 m
    :param light: lighting scale (1 full, 0.3 dimmed)
    :param light_from: direction towards the light (optical frame; (0, -1, 0) = overhead,
        which leaves the vertical cylinders only the ambient light)
    :param separation: distance between the cylinder axes
    :param extra_pairs: more (x, z, heading, separation[, show[, colors]]) cylinder pairs
        (decoys, other robots)
    :param colors: (left, right, back) albedo of the robot's cylinders
    """

    def __init__(self, robot=(0.0, 2.0, 0.0), show=('left', 'right'), posts=(), light=1.0,
                 separation=SEPARATION, extra_pairs=(), light_from=LIGHT,
                 colors=(GREEN, ORANGE, BLUE)):
        self.robot = robot
        self.colors = colors
        self.show = set(show)
        self.posts = list(posts)
        self.light = light
        self.separation = separation
        self.extra_pairs = list(extra_pairs)
        self.light_from = np.asarray(light_from, float) / np.linalg.norm(light_from)

    def truth(self):
        """dict(angle, depth, yaw, heading) of the robot, or None."""
        if self.robot is None:
            return None
        angle, depth, heading = self.robot
        yaw = (heading + angle + 180.0) % 360.0 - 180.0
        if yaw == -180.0:
            yaw = 180.0
        return {'angle': angle, 'depth': depth, 'yaw': yaw, 'heading': heading}

    def _objects(self):
        """Vertical cylinders: (x, z, radius, (h0, h1) above floor, albedo)."""
        objs = []
        pairs = list(self.extra_pairs)
        if self.robot is not None:
            angle, depth, heading = self.robot
            x, z = robot_centre(angle, depth)
            objs.append((x, z, BASE_RADIUS, BASE_SPAN, BASE_GREY))
            pairs.append((x, z, heading, self.separation, self.show, self.colors))
        for pair in pairs:
            x, z, heading, separation = pair[:4]
            show = pair[4] if len(pair) > 4 else {'left', 'right'}
            left_colour, right_colour, back_colour = pair[5] if len(pair) > 5 else (GREEN, ORANGE, BLUE)
            left, right = cylinder_centres(x, z, heading, separation)
            if 'left' in show:
                objs.append(left + (CYLINDER_RADIUS, CYLINDER_SPAN, left_colour))
            if 'right' in show:
                objs.append(right + (CYLINDER_RADIUS, CYLINDER_SPAN, right_colour))
            if 'back' in show:
                objs.append(back_centre(x, z, heading) + (CYLINDER_RADIUS, CYLINDER_SPAN, back_colour))
        for x, z, r in self.posts:
            objs.append((x, z, r, (0.0, 1.0), POST_GREY))
        return objs

    def render(self, intrinsics=None, width=WIDTH, height=HEIGHT, noise=0.0, seed=0):
        """(rgb uint8 (H, W, 3), xyz float32 (H, W, 3)); every pixel hits something.

        :param noise: std of Gaussian noise on the 8-bit colours; depth gets Kinect-like
            noise ``noise/1000 × z²`` metres when > 0
        """
        k = intrinsics or Intrinsics()
        a = ((np.arange(width, dtype=np.float32) - k.cx) / k.fx)[None, :].repeat(height, 0)
        b = ((np.arange(height, dtype=np.float32) - k.cy) / k.fy)[:, None].repeat(width, 1)
        # The back wall everywhere, then the floor below the horizon, then the objects;
        # ``colour`` holds the shaded colour (0..1) of the nearest surface so far.
        floor = b > CAMERA_HEIGHT / WALL_DEPTH
        with np.errstate(divide='ignore'):
            t = np.where(floor, CAMERA_HEIGHT / b, np.float32(WALL_DEPTH)).astype(np.float32)
        colour = np.empty((height, width, 3), np.float32)
        colour[...] = _shade(WALL_GREY, np.array([0.0, 0.0, -1.0]), self.light_from)
        colour[floor] = _shade(FLOOR_GREY, np.array([0.0, -1.0, 0.0]), self.light_from)
        with np.errstate(divide='ignore', invalid='ignore'):
            for ox, oz, r, (h0, h1), albedo in self._objects():
                window = _window(k, width, height, ox, oz, r, h0, h1)
                if window is None:
                    continue
                aw, bw = a[window], b[window]
                qa = aw * aw + 1.0
                qb = aw * ox + oz
                qc = ox * ox + oz * oz - r * r
                disc = qb * qb - qa * qc
                tt = (qb - np.sqrt(np.maximum(disc, 0.0))) / qa
                y = tt * bw
                tw = t[window]
                closer = ((disc >= 0) & (tt > 0) & (y >= CAMERA_HEIGHT - h1)
                          & (y <= CAMERA_HEIGHT - h0) & (tt < tw))
                tw[closer] = tt[closer]
                n = np.stack([(tt[closer] * aw[closer] - ox) / r, np.zeros(closer.sum()),
                              (tt[closer] - oz) / r], axis=-1)
                colour[window][closer] = _shade(albedo, n, self.light_from)
        colour *= self.light * 255.0
        rng = np.random.default_rng(seed)
        if noise > 0:
            colour += rng.standard_normal(colour.shape, np.float32) * noise
        rgb = np.clip(np.rint(colour), 0, 255).astype(np.uint8)
        z = t
        if noise > 0:
            z += rng.standard_normal(z.shape, np.float32) * (noise / 1000.0) * z * z
        xyz = np.stack([z * a, z * b, z], axis=-1)
        return rgb, xyz
