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
"""
import math

import cv2
import numpy as np

from vision_synth import geometry, literals

#: HSV ranges (OpenCV: H 0–180, S and V 0–255), inclusive. ``h`` with lo > hi wraps
#: through 0 (for reds). The low V bounds keep the cylinders under dimmed lights (~30 %).
DEFAULT_COLORS = {
    'green': {'h': [40, 90], 's': [90, 255], 'v': [10, 255]},
    'orange': {'h': [4, 24], 's': [130, 255], 'v': [12, 255]},
}

#: Agent name -> the colours of its left and right cylinders (seen from behind the robot).
DEFAULT_ROBOTS = {'faulty': {'left': 'green', 'right': 'orange'}}

#: Detector options and their defaults (the node's ~params of the same names).
DEFAULTS = {
    'pair_min': 0.22,          # m, shortest accepted distance between the cylinders
    'pair_max': 0.25,          # m, longest accepted distance
    'pair_nominal': 0.227,     # m, the real distance; the pair closest to it wins
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
    """A robot known by its cylinders: agent ``name``, ``left`` and ``right`` colour names."""
    __slots__ = ('name', 'left', 'right')

    def __init__(self, name, left, right):
        self.name, self.left, self.right = name, left, right

    def __repr__(self):
        return 'Marker(%r, left=%r, right=%r)' % (self.name, self.left, self.right)


def parse_robots(table, colors):
    """``{agent: {left: colour, right: colour}}`` -> list of :class:`Marker`, sorted by name.

    :param colors: the known colour names
    :raises ConfigError: a name that is not a Jason atom, an unknown colour, left == right
    """
    if not isinstance(table, dict) or not table:
        raise ConfigError('robots must be a non-empty mapping name -> {left, right}, got %r'
                          % (table,))
    markers = []
    for name, spec in sorted(table.items()):
        if not literals.is_atom(name):
            raise ConfigError('robot name %r is not a Jason atom' % (name,))
        if not isinstance(spec, dict) or set(spec) != {'left', 'right'}:
            raise ConfigError('robot %s needs exactly {left: colour, right: colour}, got %r'
                              % (name, spec))
        for side in ('left', 'right'):
            if spec[side] not in colors:
                raise ConfigError('robot %s: %s colour %r is not in colors (%s)'
                                  % (name, side, spec[side], ', '.join(sorted(colors))))
        if spec['left'] == spec['right']:
            raise ConfigError('robot %s: left and right colours must differ' % name)
        markers.append(Marker(name, spec['left'], spec['right']))
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
    and its ``left`` and ``right`` :class:`Blob`."""
    __slots__ = ('name', 'pose', 'left', 'right')

    def __init__(self, name, pose, left, right):
        self.name, self.pose, self.left, self.right = name, pose, left, right

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
    if not isinstance(image, np.ndarray) or not isinstance(xyz, np.ndarray):
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
        if self.min_blob_area < 1 or self.min_valid_points < 1 or self.kernel_size < 1:
            raise ConfigError('min_blob_area, min_valid_points and kernel_size must be >= 1')
        if not 0 <= self.cylinder_radius < 1 or not 0 < self.fov < 180:
            raise ConfigError('need 0 <= cylinder_radius < 1 m and 0 < fov < 180 deg')
        if self.angle_method not in ANGLE_METHODS:
            raise ConfigError('angle_method must be one of %s, got %r'
                              % (', '.join(ANGLE_METHODS), self.angle_method))
        self._kernel = np.ones((self.kernel_size, self.kernel_size), np.uint8)
        # Only the colours some robot uses are searched.
        self._used = sorted({c for m in self.markers for c in (m.left, m.right)})

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
                mask = cv2.morphologyEx(mask, cv2.MORPH_OPEN, self._kernel)
                mask = cv2.morphologyEx(mask, cv2.MORPH_CLOSE, self._kernel)
            out[name] = mask
        return out

    def blobs(self, mask, xyz, color=''):
        """Blobs of one cleaned mask with their 3-D positions; small or depth-less ones dropped.

        :param mask: (H, W) uint8
        :param xyz: (H, W, 3) float, NaN where there is no depth
        :rtype: list of :class:`Blob`
        """
        n, labels, stats, centroids = cv2.connectedComponentsWithStats(mask, connectivity=8)
        found = []
        for i in range(1, n):
            x0, y0, w, h, area = (int(s) for s in stats[i])
            if area < self.min_blob_area:
                continue
            inside = labels[y0:y0 + h, x0:x0 + w] == i
            points = np.asarray(xyz[y0:y0 + h, x0:x0 + w][inside], dtype=np.float64)
            points = points[np.isfinite(points).all(axis=1)]
            points = points[points[:, 2] > 0.0]
            if len(points) < self.min_valid_points:
                continue
            surface = np.median(points, axis=0)
            found.append(Blob(color, area, float(centroids[i][0]), float(centroids[i][1]),
                              surface, geometry.axis_point(surface, self.cylinder_radius),
                              len(points)))
        return found

    def pair(self, marker, blobs):
        """The best (left, right, separation) pair for ``marker``, or None.

        :param blobs: dict colour -> list of :class:`Blob`
        """
        best, best_error = None, None
        for left in blobs.get(marker.left, ()):
            for right in blobs.get(marker.right, ()):
                d = float(np.linalg.norm(right.axis - left.axis))
                if not self.pair_min <= d <= self.pair_max:
                    continue
                error = abs(d - self.pair_nominal)
                if best is None or error < best_error:
                    best, best_error = (left, right, d), error
        return best

    def angle_of(self, left, right, width, height, intrinsics):
        """θ of a pair by ``angle_method`` (None for 'cloud': the 3-D bearing is used)."""
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
            best = self.pair(marker, blobs)
            if best is None:
                continue
            left, right, _ = best
            angle = self.angle_of(left, right, width, height, intrinsics)
            found.append(Detection(marker.name, geometry.observe(left.axis, right.axis, angle),
                                   left, right))
        return found
