#!/usr/bin/python3
"""Writes the synthetic fixtures (ray-cast by vision_scene) into fixtures/.

    PYENV_VERSION=system /usr/bin/python3 src/vision_synth/test/make_synthetic_fixtures.py

Deterministic: running it again gives the same files. Simulator fixtures sit beside them.
"""
import vision_fixtures
import vision_scene as vs

SCENES = {
    # faulty on the left at 2.2 m, turned 40° to the right, lights at 30 %
    'synthetic_left_dim': vs.Scene((-15.0, 2.2, 40.0), light=0.3),
    # faulty on the right at 1.3 m, nearly facing the camera
    'synthetic_right_facing': vs.Scene((18.0, 1.3, -150.0)),
    # faulty in the centre at 2.5 m with its orange cylinder behind a grey post
    'synthetic_occluded': vs.Scene((3.0, 2.5, 0.0), posts=[(0.12, 1.5, 0.05)]),
}


def main():
    for name, scene in sorted(SCENES.items()):
        rgb, xyz = scene.render()  # no noise: small PNGs
        truth = scene.truth()
        if scene.show != {'left', 'right'} or scene.posts:
            expected = None
        else:
            expected = {'name': 'faulty', 'angle': truth['angle'], 'depth': truth['depth'],
                        'yaw': truth['yaw']}
        meta = {'fx': vs.FX, 'fy': vs.FY, 'cx': vs.CX, 'cy': vs.CY, 'expected': expected,
                'source': 'synthetic: test/vision_scene.py, robot (angle, depth, heading) = %r'
                          % (scene.robot,)}
        vision_fixtures.save(name, rgb, xyz, meta)
        print(name, expected)


if __name__ == '__main__':
    main()
