"""A simulated world's images written to files: each camera's RGB, depth and segmentation with its calibration,
a view from above and the overview (``roboscript render``)."""

from __future__ import annotations

import json
from pathlib import Path

import mujoco
import numpy as np
from PIL import Image

from roboscript.backends.mujoco_backend import MujocoBackend

TOP_VIEW_SIZE = (1280, 960)


def segmentation_palette(n: int) -> np.ndarray:
    """Distinct colours for ``n`` segmentation labels; index -1 (background) maps to black."""
    rng = np.random.default_rng(7)
    colors = rng.integers(60, 256, size=(max(n, 1), 3), dtype=np.uint8)
    return np.vstack([colors, np.zeros((1, 3), dtype=np.uint8)])


def top_view(backend: MujocoBackend, width: int, height: int, distance: float = 2.6) -> np.ndarray:
    """The table seen from straight above, the robot at the image's top (RGB, ``height`` x ``width`` x 3)."""
    renderer = backend.renderer(width, height)
    top = mujoco.MjvCamera()
    top.lookat[:] = [0.0, 0.0, backend.sim_world.spec.table.height]
    top.distance, top.azimuth, top.elevation = distance, 180.0, -89.9
    return renderer.rgb(backend.sim_world.data, top)


def write_snapshot(backend: MujocoBackend, out: Path) -> list[Path]:
    """Writes every camera's images and ``cameras.json`` (calibration, segmentation labels) into ``out``, plus
    ``top_view.png`` and ``overview.png``; returns the images written."""
    out.mkdir(parents=True, exist_ok=True)
    world = backend.sim_world
    labels = backend.segmentation_labels()
    palette = segmentation_palette(len(labels))
    meta: dict = {"world": world.spec.name, "robot": backend.robot.name, "cameras": {}, "segmentation_ids": labels}
    written: list[Path] = []

    def save(image: np.ndarray, name: str) -> None:
        Image.fromarray(image).save(out / name)
        written.append(out / name)

    for camera in backend.camera_names():
        frame = backend.capture(camera)
        save(frame.rgb, f"{camera}_rgb.png")
        save(np.clip(frame.depth * 1000.0, 0, 65535).astype(np.uint16), f"{camera}_depth.png")
        save(palette[frame.segmentation], f"{camera}_seg.png")
        np.save(out / f"{camera}_seg.npy", frame.segmentation)
        meta["cameras"][camera] = {
            "width": int(frame.rgb.shape[1]),
            "height": int(frame.rgb.shape[0]),
            "intrinsics": frame.intrinsics.tolist(),
            "camera_to_world": frame.extrinsics.matrix().tolist(),
            "convention": "OpenCV (x right, y down, z forward); depth PNG in millimetres",
        }
    save(top_view(backend, *TOP_VIEW_SIZE), "top_view.png")
    save(backend.render("overview", *TOP_VIEW_SIZE), "overview.png")
    (out / "cameras.json").write_text(json.dumps(meta, indent=2))
    return written
