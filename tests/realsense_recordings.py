"""Recordings of a D400-like RealSense camera, written by librealsense's own software device and recorder from frames
the simulator renders: what a test plays back through the RealSense driver in place of a camera."""

from __future__ import annotations

import gc
from pathlib import Path

import numpy as np
import pyrealsense2 as rs

from roboscript.robot_io import CameraFrame

DEPTH_UNITS = 0.001  # a D400's default: millimetres


def _intrinsics(k: np.ndarray, width: int, height: int):
    out = rs.intrinsics()
    out.width, out.height = width, height
    out.fx, out.fy, out.ppx, out.ppy = k[0, 0], k[1, 1], k[0, 2], k[1, 2]
    out.model, out.coeffs = rs.distortion.none, [0.0] * 5
    return out


def _stream(kind, index: int, width: int, height: int, fmt, bpp: int, k: np.ndarray):
    stream = rs.video_stream()
    stream.type, stream.index, stream.uid = kind, 0, index
    stream.width, stream.height, stream.fps, stream.bpp, stream.fmt = width, height, 30, bpp, fmt
    stream.intrinsics = _intrinsics(k, width, height)
    return stream


def record_d400(path: Path, serial: str, shots: list[tuple[CameraFrame, np.ndarray, np.ndarray]]) -> None:
    """Writes a recording of a D400-like camera with librealsense's recorder: per shot, the colour frame and a
    depth image (metres) with its own intrinsics, depth registered to colour with no offset."""
    device = rs.software_device()
    device.register_info(rs.camera_info.serial_number, serial)
    device.register_info(rs.camera_info.name, "Intel RealSense D435 (rendered)")
    depth_sensor, colour_sensor = device.add_sensor("Stereo Module"), device.add_sensor("RGB Camera")
    colour0, depth0, depth_k0 = shots[0]
    h, w = colour0.rgb.shape[:2]
    dh, dw = depth0.shape
    depth_profile = depth_sensor.add_video_stream(_stream(rs.stream.depth, 0, dw, dh, rs.format.z16, 2, depth_k0))
    colour_profile = colour_sensor.add_video_stream(
        _stream(rs.stream.color, 1, w, h, rs.format.rgb8, 3, colour0.intrinsics)
    )
    depth_sensor.add_read_only_option(rs.option.depth_units, DEPTH_UNITS)
    same_place = rs.extrinsics()
    same_place.rotation, same_place.translation = [1, 0, 0, 0, 1, 0, 0, 0, 1], [0.0, 0.0, 0.0]
    depth_profile.register_extrinsics_to(colour_profile, same_place)
    recorder = rs.recorder(str(path), device)
    depth_sensor.open(depth_profile)
    colour_sensor.open(colour_profile)
    queue = rs.frame_queue(16)
    depth_sensor.start(queue)
    colour_sensor.start(queue)
    for number, (colour, depth, _) in enumerate(shots):
        for sensor, profile, pixels, bpp in (
            (depth_sensor, depth_profile, np.round(depth / DEPTH_UNITS).astype(np.uint16), 2),
            (colour_sensor, colour_profile, np.ascontiguousarray(colour.rgb), 3),
        ):
            frame = rs.software_video_frame()
            frame.pixels, frame.bpp, frame.stride = pixels, bpp, bpp * pixels.shape[1]
            frame.timestamp, frame.frame_number = number * 1000.0 / 30, number
            frame.domain = rs.timestamp_domain.hardware_clock
            frame.profile = profile.as_video_stream_profile()
            if sensor is depth_sensor:
                frame.depth_units = DEPTH_UNITS
            sensor.on_video_frame(frame)
    for sensor in (depth_sensor, colour_sensor):
        sensor.stop()
        sensor.close()
    del recorder, device, depth_sensor, colour_sensor, depth_profile, colour_profile, queue
    gc.collect()  # the recorder writes its file out when librealsense lets go of it
