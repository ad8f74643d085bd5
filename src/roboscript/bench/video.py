"""Records what a camera sees during a trial into an MP4 file, so a person can watch it.

Frames are rendered every ``1 / fps`` seconds of the backend's time (simulated time in simulation) as its clock
advances (:meth:`Backend.add_clock_listener`), and piped to ffmpeg (the
binary shipped with ``imageio-ffmpeg``, the ``video`` extra).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from roboscript import extras
from roboscript.backends.base import Backend
from roboscript.errors import InvalidArgumentError

VIDEO_SIZE = (480, 360)  # width, height of a trial's video


class VideoRecorder:
    """Renders ``camera`` at ``fps`` (simulated time) into ``path`` while it is open."""

    def __init__(
        self,
        backend: Backend,
        path: str | Path,
        camera: str = "camera_left",
        fps: int = 15,
        width: int = VIDEO_SIZE[0],
        height: int = VIDEO_SIZE[1],
    ):
        try:
            import imageio_ffmpeg
        except ImportError:
            raise extras.missing("video", "--video") from None
        if camera not in backend.camera_names():
            raise InvalidArgumentError(f"no camera {camera!r} to record; cameras: {', '.join(backend.camera_names())}")
        self.backend, self.camera, self.fps = backend, camera, fps
        self.width, self.height = width, height
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._writer = imageio_ffmpeg.write_frames(
            str(self.path),
            (width, height),
            fps=fps,
            codec="libx264",
            quality=6,
            macro_block_size=8,
            pix_fmt_out="yuv420p",  # what players expect
        )
        self._writer.send(None)
        self._next = backend.time()
        self.frames = 0
        backend.add_clock_listener(self._on_tick)
        self._capture()

    def _capture(self) -> None:
        rgb = self.backend.render(self.camera, self.width, self.height)
        self._writer.send(np.ascontiguousarray(rgb).tobytes())
        self.frames += 1
        self._next += 1.0 / self.fps

    def _on_tick(self, time: float) -> None:
        if time >= self._next:
            self._capture()

    def close(self) -> None:
        if self._writer is None:
            return
        self.backend.remove_clock_listener(self._on_tick)
        self._capture()
        self._writer.close()
        self._writer = None
