"""The cameras of a robot configuration: over ROS (image, depth, calibration and segmentation topics) or a RealSense
read directly through librealsense (serial number, streams, and the pose the lab calibrated)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from roboscript.datafile import DataFileError, Reader
from roboscript.geometry import Transform


@dataclass(frozen=True)
class RealSenseSettings:
    """A RealSense camera read through librealsense: the device's serial number (or a recording of it, played back
    instead of the live camera), the colour and depth streams' size and rate, and the colour camera's pose in the
    world frame from the lab's calibration (OpenCV convention: x right, y down, z forward)."""

    serial: str
    pose: Transform
    width: int = 640
    height: int = 480
    fps: int = 30
    recording: str | None = None


@dataclass(frozen=True)
class CameraConfig:
    """One RGB-D camera. Over ROS: its image, depth and calibration topics, and an optional labelled segmentation
    topic (as a segmentation node publishes it). A RealSense read directly: ``realsense`` (the topics stay empty)."""

    name: str
    rgb: str = ""
    depth: str = ""
    info: str = ""
    segmentation: str | None = None
    realsense: RealSenseSettings | None = None

    @property
    def over_ros(self) -> bool:
        return self.realsense is None


_REALSENSE_FIELDS = {"serial", "width", "height", "fps", "recording", "position", "quaternion"}
REALSENSE_SIZES = ((424, 240), (480, 270), (640, 360), (640, 480), (848, 480), (1280, 720))  # colour and depth both
REALSENSE_RATES = (6, 15, 30, 60)


def _camera(source: str, index: int, data, error: type[DataFileError]) -> CameraConfig:
    entry = f"cameras[{index}]"
    if isinstance(data, dict) and "realsense" in data:
        reader = Reader(source, entry, data, {"name", "realsense"}, error)
        return CameraConfig(name=reader.string("name"), realsense=_realsense(source, f"{entry}.realsense", data, error))
    reader = Reader(source, entry, data, {"name", "rgb", "depth", "info", "segmentation"}, error)
    segmentation = reader.data.get("segmentation")
    return CameraConfig(
        name=reader.string("name"),
        rgb=reader.string("rgb"),
        depth=reader.string("depth"),
        info=reader.string("info"),
        segmentation=reader.string("segmentation") if segmentation is not None else None,
    )


def _realsense(source: str, entry: str, data: dict, error: type[DataFileError]) -> RealSenseSettings:
    reader = Reader(source, entry, data["realsense"], _REALSENSE_FIELDS, error)
    serial = reader.required("serial")
    if isinstance(serial, int) and not isinstance(serial, bool):
        serial = str(serial)  # YAML reads an unquoted serial number as an integer
    if not isinstance(serial, str) or not serial.strip():
        reader.fail(
            f"field 'serial' must be the camera's serial number (rs-enumerate-devices shows it), got {serial!r}"
        )
    size = (_whole(reader, "width", 640), _whole(reader, "height", 480))
    if size not in REALSENSE_SIZES:
        sizes = ", ".join(f"{w}x{h}" for w, h in REALSENSE_SIZES)
        reader.fail(f"{size[0]}x{size[1]} is no size both RealSense streams have; sizes: {sizes}")
    fps = _whole(reader, "fps", 30)
    if fps not in REALSENSE_RATES:
        reader.fail(f"fps {fps} is no RealSense rate; rates: {', '.join(map(str, REALSENSE_RATES))}")
    quaternion = np.array(reader.vector("quaternion", (4,)))
    if not 0.9 < np.linalg.norm(quaternion) < 1.1:
        reader.fail(
            f"quaternion {tuple(quaternion)} (w, x, y, z) must have length 1, got {np.linalg.norm(quaternion):.3f}"
        )
    recording = reader.data.get("recording")
    if recording is not None:
        recording = reader.string("recording")
        if not Path(recording).is_absolute() and Path(source).is_file():
            recording = str(Path(source).parent / recording)  # relative to the configuration's file
    return RealSenseSettings(
        serial=serial,
        pose=Transform.from_mujoco(np.array(reader.vector("position", (3,))), quaternion / np.linalg.norm(quaternion)),
        width=size[0],
        height=size[1],
        fps=fps,
        recording=recording,
    )


def _whole(reader: Reader, key: str, default: int) -> int:
    value = reader.number(key, default)
    if value != int(value):
        reader.fail(f"field {key!r} must be a whole number, got {value}")
    return int(value)


def parse_cameras(source: str, data, error: type[DataFileError]) -> tuple[CameraConfig, ...]:
    """A configuration's ``cameras`` list, validated: each entry's fields, and no name or serial number twice."""
    if not isinstance(data, list):
        raise error(source, "cameras", f"must be a list, got {data!r}")
    cameras = tuple(_camera(source, i, entry, error) for i, entry in enumerate(data))
    names = [c.name for c in cameras]
    serials = [c.realsense.serial for c in cameras if c.realsense is not None]
    for what, values in (("name", names), ("RealSense serial", serials)):
        repeated = sorted({v for v in values if values.count(v) > 1})
        if repeated:
            raise error(source, "cameras", f"the {what} {repeated[0]!r} is given twice; each camera needs its own")
    return cameras
