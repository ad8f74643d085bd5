"""RealSense cameras through librealsense itself: frames the simulator renders are written by librealsense's
software device and recorder, as a D400 camera's would be, and read back through the driver's pipeline, its
depth-to-colour alignment and its intrinsics (no camera needed: a recording plays back through the same code)."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest

rs = pytest.importorskip("pyrealsense2", reason="the realsense extra is not installed (make test installs it)")

from realsense_recordings import record_d400  # noqa: E402
from roboscript.backends.mujoco_backend import MujocoBackend  # noqa: E402
from roboscript.camera_config import CameraConfig, RealSenseSettings  # noqa: E402
from roboscript.drivers.base import DriverError  # noqa: E402
from roboscript.drivers.realsense import RealSenseCameras  # noqa: E402
from roboscript.robot_config import RobotConfigError, load_robot_config, parse_robot_config  # noqa: E402
from roboscript.sim.cameras import pinhole_intrinsics  # noqa: E402

SERIAL = "817612070001"
DEPTH_SIZE = (424, 240)  # the depth stream is smaller than the colour one: alignment must resample it


@pytest.fixture(scope="module")
def rendered(tmp_path_factory):
    """Two shots of a packaged world's left camera: colour at 640x480, depth rendered at 424x240, and their
    recording."""
    with MujocoBackend("world_2_pick_and_place", robot="panda", settle=0.2) as backend:
        data = backend.sim_world.data
        fovy = float(backend.sim_world.model.cam("camera_left").fovy[0])
        shots = []
        for _ in range(2):
            colour = backend.capture("camera_left")
            depth = backend.renderer(*DEPTH_SIZE, color=False).depth(data, "camera_left")
            shots.append((colour, depth, pinhole_intrinsics(fovy, *DEPTH_SIZE)))
            backend.wait(0.05)
    path = tmp_path_factory.mktemp("realsense") / "camera_left.db3"
    record_d400(path, SERIAL, shots)
    return path, shots


def _cameras(path: Path, pose, serial: str = SERIAL) -> RealSenseCameras:
    settings = RealSenseSettings(serial=serial, pose=pose, recording=str(path))
    return RealSenseCameras([CameraConfig(name="camera_left", realsense=settings)])


def test_a_rendered_frame_comes_out_of_librealsense_aligned_to_colour_with_its_calibration(rendered):
    path, shots = rendered
    colour = shots[0][0]
    cameras = _cameras(path, colour.extrinsics)
    try:
        frame = cameras.frame("camera_left", timeout=5.0, not_before=0.0)
    finally:
        cameras.close()
    assert cameras.names() == ["camera_left"]
    assert np.array_equal(frame.rgb, colour.rgb)
    assert np.allclose(frame.intrinsics, colour.intrinsics, atol=1e-3)
    assert frame.extrinsics is colour.extrinsics
    assert frame.depth.shape == colour.depth.shape and frame.depth.dtype == np.float32
    truth = colour.depth
    both = (frame.depth > 0) & (truth > 0)
    assert both.sum() > 0.85 * (truth > 0).sum()  # the smaller depth image covers the colour image
    error = np.abs(frame.depth[both] - truth[both])
    assert np.median(error) < 0.003  # resampled from 424x240 onto 640x480; millimetre units
    assert np.percentile(error, 90) < 0.02  # edges between a near and a far surface may take either


def test_frames_come_in_order_and_the_end_of_a_recording_is_a_clear_error(rendered):
    path, shots = rendered
    cameras = _cameras(path, shots[0][0].extrinsics)
    try:
        first = cameras.frame("camera_left", timeout=5.0, not_before=0.0)
        # as a backend asks after a motion: a recording's frames count as taken now, whatever they were stamped
        second = cameras.frame("camera_left", timeout=5.0, not_before=time.monotonic())
        with pytest.raises(DriverError, match=r"no frame from camera 'camera_left' .*\(the recording has ended\)"):
            cameras.frame("camera_left", timeout=1.0, not_before=0.0)
        with pytest.raises(DriverError, match="no RealSense camera 'camera_top'; cameras: camera_left"):
            cameras.frame("camera_top", timeout=1.0, not_before=0.0)
    finally:
        cameras.close()
    assert np.array_equal(first.rgb, shots[0][0].rgb) and np.array_equal(second.rgb, shots[1][0].rgb)


def test_a_recording_of_another_camera_is_refused_naming_both_serials(rendered):
    path, shots = rendered
    with pytest.raises(DriverError, match=f"configured as serial 123, but .* is serial {SERIAL}"):
        _cameras(path, shots[0][0].extrinsics, serial="123")


def test_a_configuration_names_realsense_cameras_by_serial_with_their_calibrated_pose():
    data = _config_data()
    data["cameras"] = [
        {
            "name": "camera_left",
            "realsense": {"serial": 817612070001, "position": [0.5, 0.8, 1.5], "quaternion": [1, 0, 0, 0]},
        },
        {
            "name": "camera_top",
            "realsense": {
                "serial": "A1",
                "width": 848,
                "height": 480,
                "fps": 15,
                "position": [0, 0, 2],
                "quaternion": [0, 1, 0, 0],
            },
        },
    ]
    config = parse_robot_config(data)
    left, top = config.cameras
    assert left.realsense.serial == "817612070001" and not left.over_ros  # YAML read the number as an integer
    assert (left.realsense.width, left.realsense.height, left.realsense.fps) == (640, 480, 30)
    assert np.allclose(left.realsense.pose.position, [0.5, 0.8, 1.5])
    assert (top.realsense.width, top.realsense.fps) == (848, 15)
    assert np.allclose(top.realsense.pose.rotation @ [0, 0, 1], [0, 0, -1])  # turned to look down


@pytest.mark.parametrize(
    ("realsense", "problem"),
    [
        ({"serial": "A1", "width": 700, "position": [0, 0, 1], "quaternion": [1, 0, 0, 0]}, "700x480 is no size"),
        ({"serial": "A1", "fps": 25, "position": [0, 0, 1], "quaternion": [1, 0, 0, 0]}, "fps 25 is no RealSense"),
        ({"serial": "A1", "position": [0, 0, 1], "quaternion": [2, 0, 0, 0]}, "must have length 1"),
        ({"serial": "A1", "position": [0, 0, 1]}, "missing required field 'quaternion'"),
        ({"serial": "A1", "exposure": 3, "position": [0, 0, 1], "quaternion": [1, 0, 0, 0]}, "unknown field"),
    ],
)
def test_a_bad_realsense_entry_says_what_would_be_valid(realsense, problem):
    data = _config_data()
    data["cameras"] = [{"name": "camera_left", "realsense": realsense}]
    with pytest.raises(RobotConfigError, match=problem):
        parse_robot_config(data)


def _config_data() -> dict:
    import yaml

    from roboscript.robot_config import config_path

    load_robot_config("panda_franka_ros")  # the packaged file is valid as it is
    return yaml.safe_load(config_path("panda_franka_ros").read_text())
