"""The direction a seen face looks (``get_plane_normal`` from points)."""

import numpy as np

from roboscript.perception.reconstruction.faces import plane_normal_at, prevailing_direction


def _front_with_handle() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A drawer's front in the plane x = 0 facing +x, seen every 3 mm, and a handle bar standing 3 cm out of it
    (its top, bottom and front faces), as one part's points with their normals; and the handle's middle."""
    ys, zs = np.meshgrid(np.arange(-0.1, 0.1, 0.003), np.arange(-0.06, 0.06, 0.003))
    front = np.stack([np.zeros(ys.size), ys.ravel(), zs.ravel()], axis=1)
    front_normals = np.tile([1.0, 0.0, 0.0], (len(front), 1))
    bar_y, bar_x = np.meshgrid(np.arange(-0.06, 0.06, 0.003), np.arange(0.003, 0.03, 0.003))
    top = np.stack([bar_x.ravel(), bar_y.ravel(), np.full(bar_x.size, 0.006)], axis=1)
    bottom = top * [1.0, 1.0, -1.0]
    face_y, face_z = np.meshgrid(np.arange(-0.06, 0.06, 0.003), np.arange(-0.006, 0.0061, 0.003))
    face = np.stack([np.full(face_y.size, 0.03), face_y.ravel(), face_z.ravel()], axis=1)
    points = np.concatenate([front, top, bottom, face])
    normals = np.concatenate(
        [
            front_normals,
            np.tile([0.0, 0.0, 1.0], (len(top), 1)),
            np.tile([0.0, 0.0, -1.0], (len(bottom), 1)),
            np.tile([1.0, 0.0, 0.0], (len(face), 1)),
        ]
    )
    return points, normals, np.array([0.015, 0.0, 0.0])


def test_a_front_s_normal_at_its_handle_is_the_front_s_not_the_handle_s():
    points, normals, handle = _front_with_handle()
    normal = plane_normal_at(points, handle, normals=normals)
    assert np.degrees(np.arccos(np.clip(normal @ [1.0, 0.0, 0.0], -1, 1))) < 2.0, normal
    # A plane fitted to the same points leans towards the handle's top and bottom: what the normals prevent.
    fitted = plane_normal_at(points, handle)
    assert abs(fitted @ [1.0, 0.0, 0.0]) < 0.9, fitted


def test_the_prevailing_direction_ignores_a_minority_and_says_when_there_is_none():
    rng = np.random.default_rng(0)
    up = np.tile([0.0, 0.0, 1.0], (70, 1)) + rng.normal(0.0, 0.05, (70, 3))
    side = np.tile([0.0, 1.0, 0.0], (30, 1))
    direction = prevailing_direction(np.concatenate([up / np.linalg.norm(up, axis=1, keepdims=True), side]))
    assert direction @ [0.0, 0.0, 1.0] > 0.999
    assert prevailing_direction(np.array([[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0]])) is None


def test_with_few_points_near_the_face_of_the_box_nearest_answers():
    points = np.array([[x, y, z] for x in (0.0, 0.1) for y in (0.0, 0.2) for z in (0.0, 0.05)])
    np.testing.assert_allclose(plane_normal_at(points, np.array([0.05, 0.1, 0.06])), [0.0, 0.0, 1.0])
    np.testing.assert_allclose(plane_normal_at(points, np.array([-0.01, 0.1, 0.02])), [-1.0, 0.0, 0.0])
