"""PointCloud2 / Image <-> numpy on messages built by hand (no ROS master)."""
import struct

import numpy as np
import pytest
from sensor_msgs.msg import Image, PointCloud2, PointField

from vision_synth import cloud

import vision_scene as vs


def random_frame(h, w, seed=0):
    rng = np.random.default_rng(seed)
    xyz = rng.uniform(-3, 3, (h, w, 3)).astype(np.float32)
    xyz[rng.random((h, w)) < 0.1] = np.nan
    rgb = rng.integers(0, 256, (h, w, 3), dtype=np.uint8)
    return xyz, rgb


def handmade_cloud(xyz, rgb, order=('x', 'y', 'z', 'rgb'), point_step=32, row_pad=0,
                   bigendian=False, rgb_type=PointField.FLOAT32):
    """A PointCloud2 packed point by point with struct, fields in any order/offset."""
    h, w = xyz.shape[:2]
    offsets = {name: 4 * i + (4 if i >= 2 else 0) for i, name in enumerate(order)}  # a gap
    e = '>' if bigendian else '<'
    row_step = w * point_step + row_pad
    data = bytearray(h * row_step)
    for v in range(h):
        for u in range(w):
            base = v * row_step + u * point_step
            for i, name in enumerate('xyz'):
                struct.pack_into(e + 'f', data, base + offsets[name], float(xyz[v, u, i]))
            r, g, b = (int(c) for c in rgb[v, u])
            struct.pack_into(e + 'I', data, base + offsets['rgb'], (r << 16) | (g << 8) | b)
    fields = [PointField(name=n, offset=offsets[n],
                         datatype=rgb_type if n == 'rgb' else PointField.FLOAT32, count=1)
              for n in order]
    return PointCloud2(height=h, width=w, fields=fields, is_bigendian=bigendian,
                       point_step=point_step, row_step=row_step, data=bytes(data))


@pytest.mark.parametrize('shape', [(2, 3), (5, 7), (48, 64)])
@pytest.mark.parametrize('point_step', [16, 32])
def test_round_trip(shape, point_step):
    xyz, rgb = random_frame(*shape)
    msg = cloud.arrays_to_cloud(xyz, rgb, point_step=point_step)
    assert (msg.height, msg.width, msg.point_step) == (shape[0], shape[1], point_step)
    xyz2, rgb2 = cloud.cloud_to_arrays(msg)
    np.testing.assert_array_equal(xyz2, xyz)  # NaNs in the same places
    np.testing.assert_array_equal(rgb2, rgb)


@pytest.mark.parametrize('kwargs', [
    {}, {'order': ('rgb', 'z', 'x', 'y')}, {'row_pad': 12}, {'bigendian': True},
    {'rgb_type': PointField.UINT32}, {'order': ('y', 'x', 'rgb', 'z'), 'point_step': 48}])
def test_reads_fields_where_the_message_says(kwargs):
    xyz, rgb = random_frame(4, 6, seed=3)
    xyz2, rgb2 = cloud.cloud_to_arrays(handmade_cloud(xyz, rgb, **kwargs))
    np.testing.assert_array_equal(xyz2, xyz)
    np.testing.assert_array_equal(rgb2, rgb)


def test_pcl_float_packing_is_decoded():
    """PCL stores 0x00RRGGBB's bits in a float32: (255, 128, 1) is a denormal float."""
    bits = (255 << 16) | (128 << 8) | 1
    as_float = struct.unpack('<f', struct.pack('<I', bits))[0]
    data = struct.pack('<ffff', 1.0, 2.0, 3.0, as_float)
    fields = [PointField(name=n, offset=4 * i, datatype=PointField.FLOAT32, count=1)
              for i, n in enumerate(['x', 'y', 'z', 'rgb'])]
    # an organized cloud needs height > 1: two identical rows
    msg = PointCloud2(height=2, width=1, fields=fields, point_step=16, row_step=16,
                      data=data * 2)
    xyz, rgb = cloud.cloud_to_arrays(msg)
    assert rgb[0, 0].tolist() == [255, 128, 1]
    assert xyz[1, 0].tolist() == [1.0, 2.0, 3.0]


def test_cloud_without_colour():
    xyz, rgb = random_frame(3, 4)
    msg = cloud.arrays_to_cloud(xyz, None)
    with pytest.raises(cloud.CloudError):
        cloud.cloud_to_arrays(msg)
    xyz2, none = cloud.cloud_to_arrays(msg, need_color=False)
    assert none is None
    np.testing.assert_array_equal(xyz2, xyz)


def bad(msg, **changes):
    for key, value in changes.items():
        setattr(msg, key, value)
    return msg


def change_field(msg, name, **changes):
    """``msg`` with field ``name`` changed (offset or datatype)."""
    fields = []
    for f in msg.fields:
        kw = dict(name=f.name, offset=f.offset, datatype=f.datatype, count=f.count)
        if f.name == name:
            kw.update(changes)
        fields.append(PointField(**kw))
    return bad(msg, fields=fields)


@pytest.mark.parametrize('make', [
    lambda m: bad(m, height=0, width=0, data=b''),
    lambda m: bad(m, height=1, width=12),
    lambda m: bad(m, data=m.data[:-1]),
    lambda m: bad(m, row_step=m.row_step - 1),
    lambda m: bad(m, fields=[f for f in m.fields if f.name != 'z']),
    lambda m: change_field(m, 'x', datatype=PointField.FLOAT64),
    lambda m: change_field(m, 'rgb', datatype=PointField.UINT8),
    lambda m: change_field(m, 'rgb', offset=32),  # beyond point_step
])
def test_malformed_clouds_raise_cloud_error(make):
    xyz, rgb = random_frame(3, 4)
    with pytest.raises(cloud.CloudError):
        cloud.cloud_to_arrays(make(cloud.arrays_to_cloud(xyz, rgb)))


@pytest.mark.parametrize('encoding, channels, order', [
    ('rgb8', 3, [0, 1, 2]), ('bgr8', 3, [2, 1, 0]), ('rgba8', 4, [0, 1, 2]),
    ('bgra8', 4, [2, 1, 0])])
@pytest.mark.parametrize('pad', [0, 5])
def test_images_by_encoding_and_step(encoding, channels, order, pad):
    rng = np.random.default_rng(2)
    pixels = rng.integers(0, 256, (5, 7, channels), dtype=np.uint8)
    rows = np.zeros((5, 7 * channels + pad), np.uint8)
    rows[:, :7 * channels] = pixels.reshape(5, -1)
    msg = Image(height=5, width=7, encoding=encoding, step=7 * channels + pad,
                data=rows.tobytes())
    np.testing.assert_array_equal(cloud.image_to_rgb(msg), pixels[..., order])


@pytest.mark.parametrize('msg', [
    Image(height=2, width=2, encoding='mono8', step=2, data=bytes(4)),
    Image(height=2, width=2, encoding='16UC1', step=4, data=bytes(8)),
    Image(height=0, width=0, encoding='rgb8', step=0, data=b''),
    Image(height=2, width=2, encoding='rgb8', step=6, data=bytes(11)),
    Image(height=2, width=2, encoding='rgb8', step=5, data=bytes(12)),
])
def test_bad_images_raise_cloud_error(msg):
    with pytest.raises(cloud.CloudError):
        cloud.image_to_rgb(msg)


def test_depth_to_points_inverts_the_projection():
    scene = vs.Scene((10, 2.0, 30))
    _, xyz = scene.render()
    depth = xyz[..., 2].copy()
    depth[:10] = 0.0
    points = cloud.depth_to_points(depth, vs.Intrinsics())
    assert np.isnan(points[:10]).all()
    np.testing.assert_allclose(points[10:], xyz[10:], rtol=1e-5, atol=1e-6)


def test_depth_points_windows_are_the_whole_arrays_windows():
    scene = vs.Scene((10, 2.0, 30))
    _, xyz = scene.render()
    depth = xyz[..., 2].copy()
    depth[5:40, 100:300] = 0.0  # no return
    whole = cloud.depth_to_points(depth, vs.Intrinsics())
    lazy = cloud.DepthPoints(depth, vs.Intrinsics())
    assert lazy.shape == whole.shape and lazy.dtype == whole.dtype
    for rows, cols in [(slice(0, 480), slice(0, 640)), (slice(200, 260), slice(300, 333)),
                       (slice(0, 50), slice(90, 310)), (slice(470, 500), slice(630, None))]:
        np.testing.assert_array_equal(lazy[rows, cols], whole[rows, cols])
    np.testing.assert_array_equal(np.asarray(lazy), whole)
    np.testing.assert_array_equal(lazy[3, 4], whole[3, 4])  # any other index: the whole array's


def test_rgb8_image_is_read_without_a_copy():
    pixels = np.random.default_rng(2).integers(0, 256, (4, 5, 3), dtype=np.uint8)
    msg = Image(height=4, width=5, encoding='rgb8', step=15, data=pixels.tobytes())
    rgb = cloud.image_to_rgb(msg)
    np.testing.assert_array_equal(rgb, pixels)
    assert not rgb.flags.writeable  # a view of the message's bytes


def test_depth_image_in_millimetres_and_metres_reads_as_metres_with_nan_for_no_return():
    mm = np.array([[0, 1000, 2501], [65535, 450, 0]], dtype='<u2')
    msg = Image(height=2, width=3, encoding='16UC1', step=6, data=mm.tobytes())
    np.testing.assert_allclose(cloud.depth_image_to_metres(msg),
                               [[np.nan, 1.0, 2.501], [65.535, 0.45, np.nan]], rtol=1e-6)
    big = Image(height=2, width=3, encoding='16UC1', step=6, is_bigendian=1,
                data=mm.astype('>u2').tobytes())
    np.testing.assert_array_equal(np.isnan(cloud.depth_image_to_metres(big)),
                                  np.isnan(cloud.depth_image_to_metres(msg)))
    m = np.array([[np.nan, 1.25], [0.0, 3.0]], dtype='<f4')
    msg = Image(height=2, width=2, encoding='32FC1', step=8, data=m.tobytes())
    np.testing.assert_allclose(cloud.depth_image_to_metres(msg), [[np.nan, 1.25], [np.nan, 3.0]])


@pytest.mark.parametrize('msg', [
    Image(height=2, width=2, encoding='rgb8', step=6, data=bytes(12)),
    Image(height=0, width=2, encoding='16UC1', step=4, data=b''),
    Image(height=2, width=2, encoding='16UC1', step=4, data=bytes(7)),
    Image(height=2, width=2, encoding='32FC1', step=4, data=bytes(16)),
])
def test_bad_depth_images_raise_cloud_error(msg):
    with pytest.raises(cloud.CloudError):
        cloud.depth_image_to_metres(msg)
