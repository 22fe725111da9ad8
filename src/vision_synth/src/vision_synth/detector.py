"""Coloured-cylinder detector (thesis §6.2.1): masks, blobs, pairs, poses. No ROS.

Per colour: HSV ``inRange``, a morphological opening (erode, dilate: removes specks) and a
closing (dilate, erode: fills holes, e.g. specular highlights), then connected components
("blobs"). A blob's 3-D position is the per-coordinate median of its valid (finite) points
in the organized cloud, moved back to the cylinder's axis (:func:`geometry.axis_point`);
blobs too small or with too few valid points are dropped.

Pairs: for each robot in the ``robots`` table, every (left colour, right colour) blob pair
whose axis-to-axis 3-D distance is in ``[pair_min, pair_max]`` is a candidate; the one
closest to ``pair_nominal`` wins; at most one robot per name. A single cylinder (the other
one hidden) is therefore never a robot.

A robot may carry a third cylinder (``back`` colour in its table), ``back_offset`` behind
the middle of the other two: the thesis's remedy for self-occlusion (§8.1), since from any
direction at least two of three cylinders that are not in a line are in view. Its
pairs with the left and the right cylinder are then candidates too, with the same
tolerance about their own nominal distance, and a consistent triple wins over any pair;
the pose is the rigid fit of the cylinders seen to where they sit on the robot
(:func:`geometry.fit_pose`). A single cylinder is still never a robot.
"""
import itertools
import math

import cv2
import numpy as np

from vision_synth import geometry, literals

#: HSV ranges (OpenCV: H 0–180, S and V 0–255), inclusive. ``h`` with lo > hi wraps
#: through 0 (for reds). The low V bounds keep the cylinders under dimmed lights (~30 %).
DEFAULT_COLORS = {
    'green': {'h': [40, 90], 's': [90, 255], 'v': [10, 255]},
    'orange': {'h': [4, 24], 's': [130, 255], 'v': [12, 255]},
    'blue': {'h': [100, 130], 's': [120, 255], 'v': [10, 255]},
    # the fleet's (rason_sim/config/fleet.yaml), with green and blue
    'red': {'h': [172, 8], 's': [130, 255], 'v': [10, 255]},
    'yellow': {'h': [20, 35], 's': [130, 255], 'v': [10, 255]},
    'magenta': {'h': [140, 162], 's': [130, 255], 'v': [10, 255]},
}

#: Agent name -> the colours of its left and right cylinders (seen from behind the robot)
#: and, optionally, of a third one behind their middle (``back``). A robot without the
#: third cylinder is found by the other two as before.
DEFAULT_ROBOTS = {'faulty': {'left': 'green', 'right': 'orange', 'back': 'blue'}}

#: Detector options and their defaults (the node's ~params of the same names).
DEFAULTS = {
    'pair_min': 0.22,          # m, shortest accepted distance between the cylinders
    'pair_max': 0.25,          # m, longest accepted distance
    'pair_nominal': 0.227,     # m, the real distance; the pair closest to it wins
    'back_offset': 0.12,       # m, the third cylinder behind the middle of the other two
    'min_blob_area': 30,       # pixels after opening/closing
    'min_valid_points': 10,    # blob pixels with a finite 3-D point
    'kernel_size': 3,          # pixels, square structuring element of the opening/closing
    'cylinder_radius': 0.02,   # m, 0 = report the visible surface instead of the axis
    'angle_method': 'cloud',   # cloud | pinhole | thesis (see geometry.bearing_deg)
    'fov': 57.0,               # deg, horizontal; for 'thesis', and 'pinhole' without intrinsics
}

ANGLE_METHODS = ('cloud', 'pinhole', 'thesis')


class ConfigError(ValueError):
    """A parameter is malformed (raised at construction, never per frame)."""


class FrameError(ValueError):
    """A frame cannot be processed (empty, wrong shape or type, sizes disagree)."""


class ColorRange(object):
    """An inclusive HSV range; ``h`` wraps through 0 when its low bound is above its high one.

    :param name: colour name
    :param h: (low, high) hue, 0–180
    :param s: (low, high) saturation, 0–255
    :param v: (low, high) value, 0–255
    :raises ConfigError: malformed bounds
    """

    def __init__(self, name, h, s=(0, 255), v=(0, 255)):
        self.name = name
        self.h = self._bounds(name, 'h', h, 180)
        self.s = self._bounds(name, 's', s, 255)
        self.v = self._bounds(name, 'v', v, 255)
        if self.s[0] > self.s[1] or self.v[0] > self.v[1]:
            raise ConfigError('colour %s: s and v need low <= high' % name)

    @staticmethod
    def _bounds(name, key, pair, top):
        try:
            lo, hi = (int(round(float(b))) for b in pair)
        except (TypeError, ValueError):
            raise ConfigError('colour %s: %s must be [low, high], got %r' % (name, key, pair))
        if not (0 <= lo <= top and 0 <= hi <= top):
            raise ConfigError('colour %s: %s bounds must be within 0..%d, got %r'
                              % (name, key, top, pair))
        return lo, hi

    def mask(self, hsv):
        """uint8 mask (255 inside the range) of an HSV image.

        :param hsv: (H, W, 3) uint8, OpenCV HSV
        """
        if self.h[0] <= self.h[1]:
            return cv2.inRange(hsv, (self.h[0], self.s[0], self.v[0]),
                               (self.h[1], self.s[1], self.v[1]))
        low = cv2.inRange(hsv, (self.h[0], self.s[0], self.v[0]), (180, self.s[1], self.v[1]))
        high = cv2.inRange(hsv, (0, self.s[0], self.v[0]), (self.h[1], self.s[1], self.v[1]))
        return cv2.bitwise_or(low, high)

    def __repr__(self):
        return 'ColorRange(%r, h=%r, s=%r, v=%r)' % (self.name, self.h, self.s, self.v)


def parse_colors(table):
    """``{name: {h: [lo, hi], s: [lo, hi], v: [lo, hi]}}`` -> ``{name: ColorRange}``.

    :raises ConfigError: not a mapping, or a bad range
    """
    if not isinstance(table, dict) or not table:
        raise ConfigError('colors must be a non-empty mapping name -> {h, s, v}, got %r' % (table,))
    colors = {}
    for name, spec in table.items():
        if not isinstance(spec, dict) or 'h' not in spec:
            raise ConfigError('colour %s needs at least h: [low, high], got %r' % (name, spec))
        unknown = set(spec) - {'h', 's', 'v'}
        if unknown:
            raise ConfigError('colour %s: unknown keys %s' % (name, sorted(unknown)))
        colors[str(name)] = ColorRange(str(name), spec['h'], spec.get('s', (0, 255)),
                                       spec.get('v', (0, 255)))
    return colors


class Marker(object):
    """A robot known by its cylinders: agent ``name``, ``left`` and ``right`` colour names
    and the ``back`` one's (None: the robot has two cylinders)."""
    __slots__ = ('name', 'left', 'right', 'back')

    def __init__(self, name, left, right, back=None):
        self.name, self.left, self.right, self.back = name, left, right, back

    @property
    def roles(self):
        """(role, colour) of each cylinder the robot carries."""
        roles = [('left', self.left), ('right', self.right)]
        return roles + [('back', self.back)] if self.back else roles

    def describe(self):
        """``green/orange`` or ``green/orange/blue`` (left/right[/back])."""
        return '/'.join(colour for _, colour in self.roles)

    def __repr__(self):
        return 'Marker(%r, left=%r, right=%r, back=%r)' % (self.name, self.left, self.right,
                                                            self.back)


def parse_robots(table, colors):
    """``{agent: {left: colour, right: colour[, back: colour]}}`` -> list of
    :class:`Marker`, sorted by name.

    :param colors: the known colour names
    :raises ConfigError: a name that is not a Jason atom, an unknown colour, a colour used
        twice by one robot
    """
    if not isinstance(table, dict) or not table:
        raise ConfigError('robots must be a non-empty mapping name -> {left, right}, got %r'
                          % (table,))
    markers = []
    for name, spec in sorted(table.items()):
        if not literals.is_atom(name):
            raise ConfigError('robot name %r is not a Jason atom' % (name,))
        if not isinstance(spec, dict) or set(spec) not in ({'left', 'right'},
                                                           {'left', 'right', 'back'}):
            raise ConfigError('robot %s needs {left: colour, right: colour} and optionally '
                              'back: colour, got %r' % (name, spec))
        for side in sorted(spec):
            if spec[side] not in colors:
                raise ConfigError('robot %s: %s colour %r is not in colors (%s)'
                                  % (name, side, spec[side], ', '.join(sorted(colors))))
        if len(set(spec.values())) != len(spec):
            raise ConfigError('robot %s: its cylinders must have different colours' % name)
        markers.append(Marker(name, spec['left'], spec['right'], spec.get('back')))
    return markers


class Blob(object):
    """A candidate cylinder.

    :ivar color: colour name
    :ivar area: pixels
    :ivar u: centroid column, pixels
    :ivar v: centroid row, pixels
    :ivar surface: median (x, y, z) of its valid points, metres
    :ivar axis: ``surface`` moved back to the cylinder axis
    :ivar valid: number of pixels with a finite 3-D point
    """
    __slots__ = ('color', 'area', 'u', 'v', 'surface', 'axis', 'valid')

    def __init__(self, color, area, u, v, surface, axis, valid):
        self.color, self.area, self.u, self.v = color, area, u, v
        self.surface, self.axis, self.valid = surface, axis, valid

    def __repr__(self):
        return 'Blob(%s, area=%d, u=%.1f, v=%.1f, axis=(%.3f, %.3f, %.3f))' % (
            self.color, self.area, self.u, self.v, self.axis[0], self.axis[1], self.axis[2])


class Detection(object):
    """A robot found in a frame: its agent ``name``, its ``pose`` (:class:`geometry.Pose`),
    and the :class:`Blob` of its ``left``, ``right`` and ``back`` cylinders (None: not
    seen; at least two are)."""
    __slots__ = ('name', 'pose', 'left', 'right', 'back')

    def __init__(self, name, pose, left, right, back=None):
        self.name, self.pose, self.left, self.right, self.back = name, pose, left, right, back

    def literal(self):
        """``robot(Name,Angle,Depth,Yaw)`` in Jason syntax."""
        return literals.robot_literal(self.name, self.pose.angle, self.pose.depth, self.pose.yaw)

    def __repr__(self):
        return 'Detection(%s, %r)' % (self.name, self.pose)


class Intrinsics(object):
    """Pinhole intrinsics of the colour camera (pixels)."""
    __slots__ = ('fx', 'fy', 'cx', 'cy')

    def __init__(self, fx, fy, cx, cy):
        self.fx, self.fy, self.cx, self.cy = float(fx), float(fy), float(cx), float(cy)
        if not (self.fx > 0 and self.fy > 0 and all(map(math.isfinite, (self.cx, self.cy)))):
            raise ValueError('bad intrinsics fx=%r fy=%r cx=%r cy=%r' % (fx, fy, cx, cy))

    @classmethod
    def from_fov(cls, width, height, fov_deg):
        """Square pixels, principal point at the image centre, horizontal ``fov_deg``."""
        f = geometry.focal_from_fov(width, fov_deg)
        return cls(f, f, (width - 1) / 2.0, (height - 1) / 2.0)


def check_frame(image, xyz):
    """Raise :class:`FrameError` unless ``image`` is (H, W, 3) uint8 and ``xyz`` (H, W, 3) float.

    :returns: (H, W)
    """
    # points: a numpy array, or what stands for one (cloud.DepthPoints: shape, dtype and
    # windows by slicing)
    if not isinstance(image, np.ndarray) or not all(hasattr(xyz, a) for a in ('shape', 'dtype', 'ndim')):
        raise FrameError('image and points must be numpy arrays')
    if image.ndim != 3 or image.shape[2] != 3 or image.dtype != np.uint8:
        raise FrameError('image must be (H, W, 3) uint8, got %s %s' % (image.shape, image.dtype))
    if xyz.ndim != 3 or xyz.shape[2] != 3 or xyz.dtype.kind != 'f':
        raise FrameError('points must be (H, W, 3) float, got %s %s' % (xyz.shape, xyz.dtype))
    if image.shape[:2] != xyz.shape[:2]:
        raise FrameError('image %dx%d and points %dx%d differ in size'
                         % (image.shape[1], image.shape[0], xyz.shape[1], xyz.shape[0]))
    if image.shape[0] == 0 or image.shape[1] == 0:
        raise FrameError('empty frame')
    return image.shape[:2]


class Detector(object):
    """Finds the robots of ``robots`` in (image, organized cloud) frames.

    :param colors: HSV table, see :data:`DEFAULT_COLORS` and :func:`parse_colors`
    :param robots: name -> colours table, see :data:`DEFAULT_ROBOTS`
    :param options: keys of :data:`DEFAULTS`
    :raises ConfigError: a bad parameter
    """

    def __init__(self, colors=None, robots=None, **options):
        unknown = set(options) - set(DEFAULTS)
        if unknown:
            raise ConfigError('unknown detector options: %s' % ', '.join(sorted(unknown)))
        opt = dict(DEFAULTS, **options)
        self.colors = parse_colors(DEFAULT_COLORS if colors is None else colors)
        self.markers = parse_robots(DEFAULT_ROBOTS if robots is None else robots, self.colors)
        try:
            self.pair_min = float(opt['pair_min'])
            self.pair_max = float(opt['pair_max'])
            self.pair_nominal = float(opt['pair_nominal'])
            self.back_offset = float(opt['back_offset'])
            self.min_blob_area = int(opt['min_blob_area'])
            self.min_valid_points = int(opt['min_valid_points'])
            self.kernel_size = int(opt['kernel_size'])
            self.cylinder_radius = float(opt['cylinder_radius'])
            self.fov = float(opt['fov'])
        except (TypeError, ValueError) as e:
            raise ConfigError('bad detector option: %s' % e)
        self.angle_method = opt['angle_method']
        if not 0 < self.pair_min <= self.pair_nominal <= self.pair_max:
            raise ConfigError('need 0 < pair_min <= pair_nominal <= pair_max, got %g, %g, %g'
                              % (self.pair_min, self.pair_nominal, self.pair_max))
        if not 0 < self.back_offset < 1:
            raise ConfigError('need 0 < back_offset < 1 m, got %g' % self.back_offset)
        if self.min_blob_area < 1 or self.min_valid_points < 1 or self.kernel_size < 1:
            raise ConfigError('min_blob_area, min_valid_points and kernel_size must be >= 1')
        if not 0 <= self.cylinder_radius < 1 or not 0 < self.fov < 180:
            raise ConfigError('need 0 <= cylinder_radius < 1 m and 0 < fov < 180 deg')
        if self.angle_method not in ANGLE_METHODS:
            raise ConfigError('angle_method must be one of %s, got %r'
                              % (', '.join(ANGLE_METHODS), self.angle_method))
        self._kernel = np.ones((self.kernel_size, self.kernel_size), np.uint8)
        # Only the colours some robot uses are searched.
        self._used = sorted({c for m in self.markers for _, c in m.roles})
        half = self.pair_nominal / 2.0
        # Where each cylinder sits on the robot: (forward, left) metres from its centre.
        self._layout = {'left': (0.0, half), 'right': (0.0, -half),
                        'back': (-self.back_offset, 0.0)}

    def masks(self, image, bgr=False):
        """Cleaned mask (uint8, 255 = colour) of every colour used by a robot.

        inRange, then opening (erode, dilate) and closing (dilate, erode), as in §6.2.1.

        :param image: (H, W, 3) uint8, RGB (or BGR with ``bgr=True``)
        :rtype: dict colour -> mask
        """
        hsv = cv2.cvtColor(image, cv2.COLOR_BGR2HSV if bgr else cv2.COLOR_RGB2HSV)
        out = {}
        for name in self._used:
            mask = self.colors[name].mask(hsv)
            if self.kernel_size > 1:
                self._open_close(mask)
            out[name] = mask
        return out

    def _open_close(self, mask):
        """Opening then closing of ``mask``, in place, only around its pixels: the bounding
        box of its non-zero pixels padded by twice the kernel, outside which the mask is
        and stays empty, so the result is the whole frame's (a few cylinders in 640×480)."""
        x, y, w, h = cv2.boundingRect(mask)
        if w == 0:
            return
        pad = 2 * self.kernel_size
        rows = slice(max(y - pad, 0), y + h + pad)
        cols = slice(max(x - pad, 0), x + w + pad)
        window = cv2.morphologyEx(mask[rows, cols], cv2.MORPH_OPEN, self._kernel)
        mask[rows, cols] = cv2.morphologyEx(window, cv2.MORPH_CLOSE, self._kernel)

    def blobs(self, mask, xyz, color=''):
        """Blobs of one cleaned mask with their 3-D positions; small or depth-less ones dropped.

        :param mask: (H, W) uint8
        :param xyz: (H, W, 3) float, NaN where there is no depth
        :rtype: list of :class:`Blob`
        """
        # components of the bounding box of the mask's pixels (all of them, a fraction of
        # the frame), their boxes and centroids then moved back to the frame's pixels
        bx, by, bw, bh = cv2.boundingRect(mask)
        if bw == 0:
            return []
        n, labels, stats, centroids = cv2.connectedComponentsWithStats(
            mask[by:by + bh, bx:bx + bw], connectivity=8)
        found = []
        for i in range(1, n):
            x0, y0, w, h, area = (int(s) for s in stats[i])
            if area < self.min_blob_area:
                continue
            inside = labels[y0:y0 + h, x0:x0 + w] == i
            x0, y0 = x0 + bx, y0 + by
            points = np.asarray(xyz[y0:y0 + h, x0:x0 + w][inside], dtype=np.float64)
            points = points[np.isfinite(points).all(axis=1)]
            points = points[points[:, 2] > 0.0]
            if len(points) < self.min_valid_points:
                continue
            surface = np.median(points, axis=0)
            u, v = float(centroids[i][0]) + bx, float(centroids[i][1]) + by
            found.append(Blob(color, area, u, v, surface,
                              geometry.axis_point(surface, self.cylinder_radius), len(points)))
        return found

    def _distance_error(self, role_a, blob_a, role_b, blob_b):
        """|seen − nominal| distance of two cylinders, or None outside the tolerance
        (``pair_min``/``pair_max`` about ``pair_nominal``, moved to the pair's nominal)."""
        nominal = math.dist(self._layout[role_a], self._layout[role_b])
        shift = nominal - self.pair_nominal  # exactly 0 for left/right: the thesis's bounds
        d = float(np.linalg.norm(blob_b.axis - blob_a.axis))
        if not self.pair_min + shift <= d <= self.pair_max + shift:
            return None
        return abs(d - nominal)

    def match(self, marker, blobs):
        """The cylinders of ``marker`` seen in the frame: dict role -> :class:`Blob` of
        the best consistent triple (every distance within tolerance, least summed error),
        else of the best pair; None when no two fit. For a robot with two cylinders this is
        the thesis's pair: within ``pair_min``..``pair_max``, the closest to ``pair_nominal``.

        :param blobs: dict colour -> list of :class:`Blob`
        """
        roles = marker.roles
        best, best_key = None, None
        for size in (3, 2):
            for chosen in itertools.combinations(roles, size):
                for group in itertools.product(*(blobs.get(c, ()) for _, c in chosen)):
                    error = 0.0
                    for (i, a), (j, b) in itertools.combinations(enumerate(group), 2):
                        e = self._distance_error(chosen[i][0], a, chosen[j][0], b)
                        if e is None:
                            break
                        error += e
                    else:
                        if best is None or error < best_key:
                            best, best_key = {r: g for (r, _), g in zip(chosen, group)}, error
            if best is not None:  # a triple wins over any pair
                return best
        return None

    def pose_of(self, seen, width, height, intrinsics):
        """:class:`geometry.Pose` from ``seen`` (role -> Blob, see :meth:`match`)."""
        left, right = seen.get('left'), seen.get('right')
        if set(seen) == {'left', 'right'}:  # the thesis's two cylinders, as before
            return geometry.observe(left.axis, right.axis,
                                    self.angle_of(left, right, width, height, intrinsics))
        roles = sorted(seen)
        angle, separation = None, float('nan')
        if left is not None and right is not None:
            angle = self.angle_of(left, right, width, height, intrinsics)
            separation = float(np.linalg.norm(right.axis - left.axis))
        return geometry.fit_pose([seen[r].axis for r in roles],
                                 [self._layout[r] for r in roles], angle, separation)

    def angle_of(self, left, right, width, height, intrinsics):
        """θ of a left/right pair by ``angle_method`` (None for 'cloud': the 3-D bearing is
        used, as it is for a pose found without one of the two)."""
        if self.angle_method == 'cloud':
            return None
        u = (left.u + right.u) / 2.0
        if self.angle_method == 'thesis':
            return geometry.thesis_angle_deg(u, width, self.fov)
        k = intrinsics or Intrinsics.from_fov(width, height, self.fov)
        return geometry.pinhole_angle_deg(u, k.fx, k.cx)

    def detect(self, image, xyz, intrinsics=None, bgr=False):
        """The robots seen in one frame.

        :param image: (H, W, 3) uint8 RGB (BGR with ``bgr=True``)
        :param xyz: (H, W, 3) float32/64 organized points, optical frame, NaN = no depth;
            same pixel grid as ``image``
        :param intrinsics: :class:`Intrinsics` for ``angle_method: pinhole`` (else the fov)
        :rtype: list of :class:`Detection`, sorted by name (empty: nobody seen)
        :raises FrameError: unusable frame
        """
        height, width = check_frame(image, xyz)
        masks = self.masks(image, bgr)
        blobs = {name: self.blobs(mask, xyz, name) for name, mask in masks.items()}
        found = []
        for marker in self.markers:
            seen = self.match(marker, blobs)
            if seen is None:
                continue
            found.append(Detection(marker.name, self.pose_of(seen, width, height, intrinsics),
                                   seen.get('left'), seen.get('right'), seen.get('back')))
        return found
