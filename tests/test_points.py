"""Per-entity points and normals, computed at the chosen pixels only, match the dense maps they replace."""

import numpy as np
import pytest

from roboscript.geometry import Transform
from roboscript.perception.points import entities_points, normal_map, point_map, surface_points
from roboscript.robot_io import CameraFrame


def _frame() -> CameraFrame:
    """A 60x80 view of a tilted floor (label 0) with a raised block (label 1) touching the image's left edge, a
    second block (label 2) and a hole with no depth."""
    h, w = 60, 80
    v, u = np.mgrid[0:h, 0:w]
    depth = (1.5 + 0.004 * u + 0.002 * v).astype(np.float32)
    segmentation = np.zeros((h, w), dtype=np.int32)
    depth[10:30, 0:20] -= 0.2
    segmentation[10:30, 0:20] = 1
    depth[35:55, 40:70] -= 0.1
    segmentation[35:55, 40:70] = 2
    depth[40:45, 50:55] = 0.0  # a hole in block 2: no depth there
    intrinsics = np.array([[70.0, 0.0, 40.0], [0.0, 70.0, 30.0], [0.0, 0.0, 1.0]])
    pose = Transform.from_rotation(np.array([0.1, -0.2, 1.8]), np.diag([1.0, -1.0, -1.0]))
    return CameraFrame("test", np.zeros((h, w, 3), np.uint8), depth, segmentation, intrinsics, pose)


def _dense(frame: CameraFrame, entity: int, stride: int) -> tuple[np.ndarray, np.ndarray]:
    """The dense computation: whole-image maps, the entity's pixels whose four neighbours are its too."""
    world = point_map(frame)
    normals = normal_map(world, frame.extrinsics.position)
    mask = frame.segmentation == entity
    inner = mask.copy()
    inner[1:] &= mask[:-1]
    inner[:-1] &= mask[1:]
    inner[:, 1:] &= mask[:, :-1]
    inner[:, :-1] &= mask[:, 1:]
    keep = np.zeros_like(inner)
    keep[::stride, ::stride] = True
    inner &= keep
    p, n = world[inner], normals[inner]
    ok = np.isfinite(p).all(axis=1) & np.isfinite(n).all(axis=1)
    return p[ok], n[ok]


@pytest.mark.parametrize("stride", [1, 2, 3])
def test_entities_points_match_the_dense_maps(stride):
    frame = _frame()
    found = entities_points([frame, frame], [0, 1, 2, 7], stride)
    for entity in (0, 1, 2):
        points, normals = _dense(frame, entity, stride)
        assert len(points) > 0
        np.testing.assert_allclose(found[entity][0], np.vstack([points, points]), atol=1e-12)
        np.testing.assert_allclose(found[entity][1], np.vstack([normals, normals]), atol=1e-12)
    assert found[7][0].shape == (0, 3)  # an entity no frame shows
    # Normals face the camera: the floor's and the blocks' point back up towards it.
    assert (found[1][1] @ np.array([0.0, 0.0, 1.0]) > 0.9).all()


def test_pixels_on_the_image_edge_and_beside_a_hole_are_left_out():
    frame = _frame()
    found = entities_points([frame], [1, 2], 1)
    camera = frame.extrinsics.inverse().apply(found[1][0])
    columns = np.round(camera[:, 0] / camera[:, 2] * frame.intrinsics[0, 0] + frame.intrinsics[0, 2])
    assert columns.min() == 1  # column 0 has no left neighbour: no normal there
    block = found[2][0]
    assert np.isfinite(block).all()
    # Not the block's outline, not the 5x5 hole, nor the 20 pixels beside it whose normals would need its depth.
    assert len(block) == 18 * 28 - 5 * 5 - 4 * 5


@pytest.mark.parametrize("stride", [1, 2, 3])
def test_surface_points_are_the_dense_map_strided_less_the_hidden_pixels(stride):
    frame = _frame()
    hidden = frame.segmentation == 1  # as if block 1 were the robot
    found = surface_points([frame, frame], [hidden, None], stride)
    masked = point_map(frame, hidden)[::stride, ::stride].reshape(-1, 3)
    whole = point_map(frame)[::stride, ::stride].reshape(-1, 3)
    expected = np.vstack([masked[np.isfinite(masked).all(axis=1)], whole[np.isfinite(whole).all(axis=1)]])
    assert len(masked[np.isfinite(masked).all(axis=1)]) < len(whole[np.isfinite(whole).all(axis=1)])
    np.testing.assert_allclose(found, expected, atol=1e-12)
