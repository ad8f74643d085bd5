"""Foxglove's message types as JSON (the MCAP channels' ``json`` encoding), built from the project's geometry.

Foxglove Studio recognises a channel by its schema's name (``foxglove.SceneUpdate``) and reads the fields by the
names its schemas give them, so these builders follow those names; times are simulated seconds as
``{sec, nsec}``. Every entity lives in the ``world`` frame.
"""

from __future__ import annotations

import base64
import math
from collections.abc import Sequence

import numpy as np

from roboscript.geometry import Box3D, Transform

WORLD = "world"
LOG_LEVELS = {"info": 2, "warning": 3, "error": 4}


def stamp(seconds: float) -> dict:
    nanoseconds = max(0, round(seconds * 1e9))
    return {"sec": nanoseconds // 1_000_000_000, "nsec": nanoseconds % 1_000_000_000}


def _vector(v: Sequence[float]) -> dict:
    return {"x": float(v[0]), "y": float(v[1]), "z": float(v[2])}


def pose(transform: Transform) -> dict:
    q = transform.quaternion
    return {"position": _vector(transform.position), "orientation": {"x": float(q[0]), "y": float(q[1]),
            "z": float(q[2]), "w": float(q[3])}}  # fmt: skip


def colour(r: float, g: float, b: float, a: float = 1.0) -> dict:
    return {"r": r, "g": g, "b": b, "a": a}


def box_cube(box: Box3D, rgba: tuple[float, float, float, float]) -> dict:
    return {"pose": pose(Transform(box.center, np.array([0.0, 0.0, 0.0, 1.0]))), "size": _vector(box.size),
            "color": colour(*rgba)}  # fmt: skip


def label(text: str, position: Sequence[float]) -> dict:
    at = Transform(np.asarray(position, dtype=float), np.array([0.0, 0.0, 0.0, 1.0]))
    return {"pose": pose(at), "billboard": True, "font_size": 12.0, "scale_invariant": True,
            "color": colour(1, 1, 1), "text": text}  # fmt: skip


def line_strip(points: np.ndarray, rgba: tuple[float, float, float, float], thickness: float = 3.0) -> dict:
    return {"type": 0, "pose": pose(Transform.identity()), "thickness": thickness, "scale_invariant": True,
            "points": [_vector(p) for p in np.asarray(points).reshape(-1, 3)], "color": colour(*rgba),
            "colors": [], "indices": []}  # fmt: skip


def entity(time: float, entity_id: str, cubes=(), lines=(), texts=()) -> dict:
    return {"timestamp": stamp(time), "frame_id": WORLD, "id": entity_id, "lifetime": stamp(0),
            "frame_locked": False, "metadata": [], "arrows": [], "cubes": list(cubes), "spheres": [],
            "cylinders": [], "lines": list(lines), "triangles": [], "texts": list(texts), "models": []}  # fmt: skip


def scene_update(entities: Sequence[dict], deletions: Sequence[dict] = ()) -> dict:
    return {"deletions": list(deletions), "entities": list(entities)}


def delete_all(time: float) -> dict:
    return {"timestamp": stamp(time), "type": 1, "id": ""}


def frame_transform(time: float, child: str, transform: Transform, parent: str = WORLD) -> dict:
    q = transform.quaternion
    return {"timestamp": stamp(time), "parent_frame_id": parent, "child_frame_id": child,
            "translation": _vector(transform.position),
            "rotation": {"x": float(q[0]), "y": float(q[1]), "z": float(q[2]), "w": float(q[3])}}  # fmt: skip


def compressed_image(time: float, frame_id: str, jpeg: bytes) -> dict:
    return {"timestamp": stamp(time), "frame_id": frame_id, "data": base64.b64encode(jpeg).decode(),
            "format": "jpeg"}  # fmt: skip


def camera_calibration(time: float, frame_id: str, width: int, height: int, fovy_deg: float) -> dict:
    """A pinhole camera of ``fovy_deg`` vertical field of view, square pixels, no distortion."""
    f = height / 2 / math.tan(math.radians(fovy_deg) / 2)
    cx, cy = width / 2, height / 2
    return {"timestamp": stamp(time), "frame_id": frame_id, "width": width, "height": height,
            "distortion_model": "plumb_bob", "D": [0.0] * 5, "K": [f, 0, cx, 0, f, cy, 0, 0, 1],
            "R": [1, 0, 0, 0, 1, 0, 0, 0, 1], "P": [f, 0, cx, 0, 0, f, cy, 0, 0, 0, 1, 0]}  # fmt: skip


def log(time: float, level: str, name: str, message: str) -> dict:
    return {"timestamp": stamp(time), "level": LOG_LEVELS[level], "message": message, "name": name, "file": "",
            "line": 0}  # fmt: skip
