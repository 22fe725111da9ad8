"""Recorded frames for the fixture-driven test: ``fixtures/<name>_rgb.png`` (colour image),
``fixtures/<name>_depth.png`` (uint16 millimetres, 0 = no return) and ``fixtures/<name>.json``
``{"fx", "fy", "cx", "cy", "expected": null | {"name", "angle", "depth", "yaw"}}``.

Angle and Yaw in degrees, positive to the right/clockwise (see vision_synth.geometry);
Depth is the optical-axis depth of the robot's centre, metres.
"""
import glob
import json
import os

import cv2
import numpy as np

from vision_synth import cloud

FIXTURES = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'fixtures')


class Intrinsics(object):
    def __init__(self, fx, fy, cx, cy):
        self.fx, self.fy, self.cx, self.cy = float(fx), float(fy), float(cx), float(cy)


def names(folder=FIXTURES):
    """Names of the complete fixtures in ``folder``, sorted."""
    found = []
    for meta in sorted(glob.glob(os.path.join(folder, '*.json'))):
        name = os.path.basename(meta)[:-len('.json')]
        if all(os.path.exists(os.path.join(folder, name + s)) for s in ('_rgb.png', '_depth.png')):
            found.append(name)
    return found


def load(name, folder=FIXTURES):
    """(rgb (H, W, 3) uint8, xyz (H, W, 3) float32 NaN = no return, meta dict)."""
    base = os.path.join(folder, name)
    bgr = cv2.imread(base + '_rgb.png', cv2.IMREAD_COLOR)
    depth = cv2.imread(base + '_depth.png', cv2.IMREAD_ANYDEPTH)
    if bgr is None or depth is None:
        raise IOError('cannot read fixture %s' % base)
    if depth.dtype != np.uint16:
        raise IOError('%s_depth.png must be 16-bit millimetres, got %s' % (base, depth.dtype))
    with open(base + '.json') as f:
        meta = json.load(f)
    rgb = cv2.cvtColor(bgr, cv2.COLOR_BGR2RGB)
    k = Intrinsics(meta['fx'], meta['fy'], meta['cx'], meta['cy'])
    xyz = cloud.depth_to_points(depth.astype(np.float32) / 1000.0, k)
    return rgb, xyz, meta


def save(name, rgb, xyz, meta, folder=FIXTURES):
    """Write a fixture from an RGB image and organized points (z used, NaN -> 0)."""
    base = os.path.join(folder, name)
    z = np.nan_to_num(xyz[..., 2], nan=0.0)
    depth = np.clip(np.rint(z * 1000.0), 0, 65535).astype(np.uint16)
    cv2.imwrite(base + '_rgb.png', cv2.cvtColor(rgb, cv2.COLOR_RGB2BGR))
    cv2.imwrite(base + '_depth.png', depth)
    with open(base + '.json', 'w') as f:
        json.dump(meta, f, indent=1, sort_keys=True)
        f.write('\n')
