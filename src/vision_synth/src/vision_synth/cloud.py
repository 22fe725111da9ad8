"""sensor_msgs PointCloud2 / Image <-> numpy, without copying when possible. No rospy.

Fields are located by the message's own ``fields`` offsets, ``point_step``, ``row_step`` and
``is_bigendian`` (never assumed). ``sensor_msgs.point_cloud2.read_points`` is a Python loop
(hundreds of ms for 640×480); these are numpy views (tens of µs to a few ms).
"""
import numpy as np

from sensor_msgs.msg import PointCloud2, PointField

#: PointField datatype -> numpy kind letter + size.
_NUMPY_TYPES = {
    PointField.INT8: 'i1', PointField.UINT8: 'u1', PointField.INT16: 'i2',
    PointField.UINT16: 'u2', PointField.INT32: 'i4', PointField.UINT32: 'u4',
    PointField.FLOAT32: 'f4', PointField.FLOAT64: 'f8',
}

#: Image encodings this package reads -> (channels, indices of R, G, B).
_ENCODINGS = {'rgb8': (3, (0, 1, 2)), 'bgr8': (3, (2, 1, 0)),
              'rgba8': (4, (0, 1, 2)), 'bgra8': (4, (2, 1, 0))}


class CloudError(ValueError):
    """A message that cannot be turned into arrays (bad layout, missing field, encoding)."""


def _field_view(msg, field, rows, endian):
    """(H, W) numpy view of one scalar field of a PointCloud2 (no copy)."""
    kind = _NUMPY_TYPES.get(field.datatype)
    if kind is None:
        raise CloudError('field %s has unknown datatype %d' % (field.name, field.datatype))
    if field.offset + int(kind[1]) > msg.point_step:
        raise CloudError('field %s at offset %d does not fit in point_step %d'
                         % (field.name, field.offset, msg.point_step))
    return np.ndarray((msg.height, msg.width), dtype=np.dtype(endian + kind), buffer=rows,
                      offset=field.offset, strides=(msg.row_step, msg.point_step))


def _check_layout(msg):
    h, w = msg.height, msg.width
    if h == 0 or w == 0:
        raise CloudError('empty cloud (%dx%d)' % (w, h))
    if h == 1:
        raise CloudError('cloud is not organized (height 1); an organized cloud is needed')
    if msg.point_step <= 0 or msg.row_step < w * msg.point_step:
        raise CloudError('bad layout: width %d, point_step %d, row_step %d'
                         % (w, msg.point_step, msg.row_step))
    if len(msg.data) < (h - 1) * msg.row_step + w * msg.point_step:
        raise CloudError('data has %d bytes, layout needs %d'
                         % (len(msg.data), (h - 1) * msg.row_step + w * msg.point_step))


def cloud_to_arrays(msg, need_color=True):
    """Organized PointCloud2 -> ``(xyz, rgb)``.

    :param msg: sensor_msgs/PointCloud2 with FLOAT32 x, y, z (and ``rgb`` or ``rgba`` packed
        as 0x00RRGGBB in 4 bytes, FLOAT32 or UINT32, as PCL does)
    :param need_color: raise if there is no colour field (else ``rgb`` is None)
    :returns: xyz (H, W, 3) float32 (a read-only view when x, y, z are consecutive),
        rgb (H, W, 3) uint8 or None
    :raises CloudError: unusable message
    """
    _check_layout(msg)
    fields = {f.name: f for f in msg.fields}
    for name in 'xyz':
        f = fields.get(name)
        if f is None:
            raise CloudError('cloud has no %s field (fields: %s)' % (name, ', '.join(fields)))
        if f.datatype != PointField.FLOAT32 or f.count not in (0, 1):
            raise CloudError('field %s must be one FLOAT32' % name)
    endian = '>' if msg.is_bigendian else '<'
    data = msg.data
    if isinstance(data, list):  # a message built by hand with a list of ints
        data = bytes(data)
    x, y, z = (fields[n].offset for n in 'xyz')
    if y == x + 4 and z == x + 8:
        xyz = np.ndarray((msg.height, msg.width, 3), dtype=np.dtype(endian + 'f4'), buffer=data,
                         offset=x, strides=(msg.row_step, msg.point_step, 4))
    else:
        xyz = np.stack([_field_view(msg, fields[n], data, endian) for n in 'xyz'], axis=-1)
    color = fields.get('rgb') or fields.get('rgba')
    if color is None:
        if need_color:
            raise CloudError('cloud has no rgb field; use the image (~use_image) instead')
        return xyz, None
    if color.datatype not in (PointField.FLOAT32, PointField.UINT32, PointField.INT32):
        raise CloudError('field %s must be 4 bytes (FLOAT32 or UINT32)' % color.name)
    packed = _field_view(msg, color, data, endian)
    packed = packed.view(np.dtype(endian + 'u4'))  # the float's bits are 0x00RRGGBB
    rgb = np.empty((msg.height, msg.width, 3), np.uint8)
    rgb[..., 0] = packed >> 16
    rgb[..., 1] = packed >> 8
    rgb[..., 2] = packed
    return xyz, rgb


def arrays_to_cloud(xyz, rgb=None, frame_id='camera_rgb_optical_frame', stamp=None,
                    point_step=16):
    """numpy -> organized PointCloud2 with fields x, y, z (and rgb packed in a FLOAT32).

    :param xyz: (H, W, 3) float, NaN allowed
    :param rgb: (H, W, 3) uint8 or None
    :param point_step: bytes per point, >= 16 (padding is left zero)
    :rtype: sensor_msgs/PointCloud2
    """
    h, w = xyz.shape[:2]
    point_step = max(int(point_step), 16 if rgb is not None else 12)
    buf = np.zeros((h, w, point_step), np.uint8)
    buf[..., 0:12] = np.ascontiguousarray(xyz, dtype='<f4').view(np.uint8).reshape(h, w, 12)
    fields = [PointField(name=n, offset=4 * i, datatype=PointField.FLOAT32, count=1)
              for i, n in enumerate('xyz')]
    if rgb is not None:
        rgb = np.asarray(rgb, np.uint32)
        packed = (rgb[..., 0] << 16) | (rgb[..., 1] << 8) | rgb[..., 2]
        buf[..., 12:16] = packed.astype('<u4').view(np.uint8).reshape(h, w, 4)
        fields.append(PointField(name='rgb', offset=12, datatype=PointField.FLOAT32, count=1))
    msg = PointCloud2(height=h, width=w, fields=fields, is_bigendian=False,
                      point_step=point_step, row_step=w * point_step, data=buf.tobytes(),
                      is_dense=False)
    msg.header.frame_id = frame_id
    if stamp is not None:
        msg.header.stamp = stamp
    return msg


def image_to_rgb(msg):
    """sensor_msgs/Image (rgb8, bgr8, rgba8, bgra8) -> (H, W, 3) uint8 RGB (for rgb8 a
    view of the message's data, read-only when the data is bytes).

    :raises CloudError: empty image, unknown encoding, data too short
    """
    enc = _ENCODINGS.get(msg.encoding.lower())
    if enc is None:
        raise CloudError('unsupported image encoding %r (need one of %s)'
                         % (msg.encoding, ', '.join(sorted(_ENCODINGS))))
    channels, order = enc
    h, w = msg.height, msg.width
    if h == 0 or w == 0:
        raise CloudError('empty image (%dx%d)' % (w, h))
    if msg.step < w * channels or len(msg.data) < (h - 1) * msg.step + w * channels:
        raise CloudError('image %dx%d %s: step %d and %d bytes do not fit'
                         % (w, h, msg.encoding, msg.step, len(msg.data)))
    data = msg.data
    if isinstance(data, list):
        data = bytes(data)
    view = np.ndarray((h, w, channels), np.uint8, buffer=data, strides=(msg.step, channels, 1))
    if order == (0, 1, 2) and channels == 3:
        return view  # rgb8 as it came: a (read-only) view, no copy of ~1 MB per frame
    return np.ascontiguousarray(view[..., list(order)])


#: Depth image encodings (REP 118) -> (numpy dtype, metres per unit).
_DEPTH_ENCODINGS = {'16uc1': ('u2', 0.001), 'mono16': ('u2', 0.001), '32fc1': ('f4', 1.0)}


def depth_image_to_metres(msg):
    """sensor_msgs/Image of depth (16UC1 millimetres or 32FC1 metres, REP 118) -> (H, W)
    float32 metres, NaN where there is no return (0, NaN).

    :raises CloudError: empty image, unknown encoding, data too short
    """
    enc = _DEPTH_ENCODINGS.get(msg.encoding.lower())
    if enc is None:
        raise CloudError('unsupported depth encoding %r (need one of 16UC1, 32FC1)'
                         % (msg.encoding,))
    kind, scale = enc
    h, w = msg.height, msg.width
    size = np.dtype(kind).itemsize
    if h == 0 or w == 0:
        raise CloudError('empty depth image (%dx%d)' % (w, h))
    if msg.step < w * size or len(msg.data) < (h - 1) * msg.step + w * size:
        raise CloudError('depth image %dx%d %s: step %d and %d bytes do not fit'
                         % (w, h, msg.encoding, msg.step, len(msg.data)))
    data = msg.data
    if isinstance(data, list):
        data = bytes(data)
    dtype = np.dtype(kind).newbyteorder('>' if msg.is_bigendian else '<')
    view = np.ndarray((h, w), dtype, buffer=data, strides=(msg.step, size))
    metres = view.astype(np.float32) * np.float32(scale)
    metres[~(metres > 0)] = np.nan
    return metres


def depth_to_points(depth, intrinsics):
    """Depth image (metres, NaN or 0 = no return) -> organized points (H, W, 3) float32.

    ``x = (u − cx)·z / fx``, ``y = (v − cy)·z / fy``, ``z = depth`` (optical frame).

    :param depth: (H, W) float
    :param intrinsics: object with fx, fy, cx, cy
    """
    return _project(np.asarray(depth, np.float32), intrinsics, 0, 0)


def _project(z, intrinsics, row0, col0):
    """Points of the depth window ``z`` whose top-left pixel is (row0, col0)."""
    z = np.where(z > 0, z, np.float32(np.nan))
    h, w = z.shape
    u = (np.arange(col0, col0 + w, dtype=np.float32) - intrinsics.cx) / intrinsics.fx
    v = (np.arange(row0, row0 + h, dtype=np.float32) - intrinsics.cy) / intrinsics.fy
    return np.stack([z * u[None, :], z * v[:, None], z], axis=-1)


class DepthPoints(object):
    """The organized points of a depth image, computed only for the windows asked for.

    Stands for ``depth_to_points(depth, intrinsics)`` where a detector reads points only
    inside its blobs' bounding boxes: ``points[r0:r1, c0:c1]`` is that array's window (the
    same values), the whole array is built only by ``np.asarray(points)``. Saves building
    ~3.7 MB of points per 640×480 frame.

    :param depth: (H, W) float metres, NaN or 0 = no return
    :param intrinsics: object with fx, fy, cx, cy
    """

    ndim = 3
    dtype = np.dtype(np.float32)

    def __init__(self, depth, intrinsics):
        self._depth = np.asarray(depth, np.float32)
        if self._depth.ndim != 2:
            raise CloudError('depth must be (H, W), got shape %s' % (self._depth.shape,))
        self._intrinsics = intrinsics
        self.shape = self._depth.shape + (3,)

    def __getitem__(self, key):
        if (isinstance(key, tuple) and len(key) == 2
                and all(isinstance(k, slice) and k.step in (None, 1) for k in key)):
            rows, cols = (range(*k.indices(n)) for k, n in zip(key, self._depth.shape))
            return _project(self._depth[key], self._intrinsics, rows.start, cols.start)
        return np.asarray(self)[key]

    def __array__(self, dtype=None):
        points = depth_to_points(self._depth, self._intrinsics)
        return points if dtype is None else points.astype(dtype)
