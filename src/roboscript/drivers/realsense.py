"""RealSense cameras through librealsense (``pyrealsense2``, the ``realsense`` extra): colour, depth aligned to
colour by librealsense's own alignment, the colour stream's intrinsics from the device, and the camera's pose from
the robot configuration.

A camera is a live device found by its serial number, or a recording of one (a ``.bag`` or ``.db3`` file that
``rs.recorder`` wrote) played back through the same pipeline, alignment and intrinsics code, frame by frame.
"""

from __future__ import annotations

import contextlib
import datetime
import logging
import math
import time
from collections.abc import Sequence

import numpy as np

from roboscript import extras
from roboscript.camera_config import CameraConfig, RealSenseSettings
from roboscript.drivers.base import CameraSource, DriverError
from roboscript.robot_io import CameraFrame

log = logging.getLogger(__name__)

START_TIMEOUT = 5.0  # seconds for a camera's first frame after its pipeline starts (a USB camera powers up)


def _rs():
    try:
        import pyrealsense2
    except ImportError as error:
        raise DriverError(extras.missing_text("realsense", "RealSense cameras")) from error
    return pyrealsense2


class RealSenseCamera:
    """One RealSense camera, streaming from when it is made until :meth:`close`."""

    def __init__(self, name: str, settings: RealSenseSettings):
        rs = _rs()
        self.name, self.settings = name, settings
        self._rs = rs
        self._pipeline = rs.pipeline()
        config = rs.config()
        if settings.recording:
            config.enable_device_from_file(settings.recording, repeat_playback=False)
        else:
            config.enable_device(settings.serial)
            config.enable_stream(rs.stream.depth, settings.width, settings.height, rs.format.z16, settings.fps)
            config.enable_stream(rs.stream.color, settings.width, settings.height, rs.format.rgb8, settings.fps)
        try:
            profile = self._pipeline.start(config)
        except RuntimeError as error:
            where = f"the recording {settings.recording}" if settings.recording else f"serial {settings.serial}"
            raise DriverError(f"camera {name!r}: librealsense could not start {where}: {error}") from None
        try:
            self._intrinsics = self._check(profile)
        except BaseException:
            self._pipeline.stop()
            raise
        self._align = rs.align(rs.stream.color)
        self._streaming = False  # until the first frame: a camera just started may take START_TIMEOUT to send one
        # A recording's frames are given once each, in order: one queued as the pipeline began playing, before the
        # seek back to the start, comes again after it (a busy machine's full test run saw three of two frames).
        self._last_recorded = -math.inf

    def _check(self, profile) -> np.ndarray:
        """Checks the started device against the configuration; returns the colour stream's intrinsics."""
        rs, settings = self._rs, self.settings
        device = profile.get_device()
        if settings.recording:
            # Every recorded frame, however slowly asked for; the pipeline began playing in real time as it started,
            # and may have dropped a frame already, so play from the beginning again.
            playback = device.as_playback()
            playback.set_real_time(False)
            playback.seek(datetime.timedelta(0))
        serial = device.get_info(rs.camera_info.serial_number)
        if serial != settings.serial:
            raise DriverError(
                f"camera {self.name!r} is configured as serial {settings.serial}, but "
                f"{settings.recording or 'the device'} is serial {serial}"
            )
        return _matrix(profile.get_stream(rs.stream.color).as_video_stream_profile().get_intrinsics())

    def frame(self, timeout: float, not_before: float) -> CameraFrame:
        """The first frame captured at ``not_before`` (``time.monotonic`` seconds) or later, within ``timeout``
        seconds; depth in metres aligned to the colour image, 0 where the camera measured nothing."""
        rs = self._rs
        timeout = timeout if self._streaming else max(timeout, START_TIMEOUT)
        deadline = time.monotonic() + timeout
        while True:
            left = deadline - time.monotonic()
            ok, frames = self._pipeline.try_wait_for_frames(max(1, int(left * 1000)))
            # a recording's stamps are of when it was recorded: its frames count as taken now, in order
            if ok and self.settings.recording:
                stamp = frames.get_timestamp()
                if stamp > self._last_recorded:
                    self._last_recorded = stamp
                    break
                continue
            if ok and _captured(frames, rs) >= not_before:
                break
            if time.monotonic() >= deadline or (not ok and self.settings.recording):
                ended = " (the recording has ended)" if self.settings.recording and not ok else ""
                raise DriverError(f"no frame from camera {self.name!r} within {timeout:.1f} s{ended}")
        self._streaming = True
        aligned = self._align.process(frames)
        depth_frame, color_frame = aligned.get_depth_frame(), aligned.get_color_frame()
        if not depth_frame or not color_frame:
            raise DriverError(f"camera {self.name!r} gave a frame without both depth and colour")
        depth = np.asanyarray(depth_frame.get_data()).astype(np.float32) * np.float32(depth_frame.get_units())
        return CameraFrame(
            name=self.name,
            rgb=np.asanyarray(color_frame.get_data()).copy(),
            depth=depth,
            segmentation=None,
            intrinsics=self._intrinsics.copy(),
            extrinsics=self.settings.pose,
        )

    def close(self) -> None:
        with contextlib.suppress(RuntimeError):  # already stopped
            self._pipeline.stop()


class RealSenseCameras(CameraSource):
    """The RealSense cameras of a robot configuration, each streaming from when this is made."""

    def __init__(self, cameras: Sequence[CameraConfig]):
        self._cameras: dict[str, RealSenseCamera] = {}
        try:
            for camera in cameras:
                if camera.realsense is None:
                    raise DriverError(f"camera {camera.name!r} is not a RealSense one (it has ROS topics)")
                self._cameras[camera.name] = RealSenseCamera(camera.name, camera.realsense)
        except BaseException:
            self.close()
            raise

    def names(self) -> list[str]:
        return list(self._cameras)

    def frame(self, camera: str, timeout: float, not_before: float) -> CameraFrame:
        if camera not in self._cameras:
            raise DriverError(f"no RealSense camera {camera!r}; cameras: {', '.join(self._cameras) or 'none'}")
        return self._cameras[camera].frame(timeout, not_before)

    def close(self) -> None:
        for camera in self._cameras.values():
            camera.close()


def _matrix(intrinsics) -> np.ndarray:
    if any(abs(c) > 1e-3 for c in intrinsics.coeffs):
        # Perception projects through a pinhole; a D400's colour stream is close to one (coefficients near 0).
        log.info("camera distortion %s (%s) is left uncorrected", list(intrinsics.coeffs), intrinsics.model)
    return np.array([[intrinsics.fx, 0, intrinsics.ppx], [0, intrinsics.fy, intrinsics.ppy], [0, 0, 1.0]])


def _captured(frames, rs) -> float:
    """When ``frames`` was captured, on this process's ``time.monotonic`` clock: the device's system-time stamp
    where it gives one on the host's clock (system time, or global time: the device's clock mapped onto the
    host's), else now (the frame has just arrived)."""
    now = time.monotonic()
    if frames.get_frame_timestamp_domain() in (rs.timestamp_domain.system_time, rs.timestamp_domain.global_time):
        return now - (time.time() - frames.get_timestamp() / 1000.0)
    return now
