"""Chooses MuJoCo's offscreen GL backend before MuJoCo is imported.

MuJoCo reads ``MUJOCO_GL`` once, at import. Headless machines have no display for GLFW, so unless the user chose,
use EGL where its library is present (Mesa renders on the CPU through it), else OSMesa.
"""

from __future__ import annotations

import ctypes.util
import os


def choose_gl_backend() -> str | None:
    if "MUJOCO_GL" in os.environ:
        return os.environ["MUJOCO_GL"]
    if os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"):
        return None  # a desktop session: MuJoCo's default (GLFW) works
    for backend, library in (("egl", "EGL"), ("osmesa", "OSMesa")):
        if ctypes.util.find_library(library):
            os.environ["MUJOCO_GL"] = backend
            os.environ.setdefault("PYOPENGL_PLATFORM", backend)
            return backend
    return None
