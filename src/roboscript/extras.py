"""The optional parts of RoboScript (``pyproject`` extras): whether one is installed, and the one way every message
says how to install it.

A command checks what its options need before any trial starts (:func:`require`), so a missing part is a usage
error with an install hint, not a traceback inside a failed trial.
"""

from __future__ import annotations

import importlib.util
import sys
from dataclasses import dataclass
from pathlib import Path

from roboscript.errors import MissingExtraError


@dataclass(frozen=True)
class Extra:
    """An extra: the modules it brings (all must import), what it brings in a person's words, and what still works
    without it (said with every message about it, where there is something to say)."""

    name: str
    modules: tuple[str, ...]
    brings: str
    without: str = ""


EXTRAS = {
    e.name: e
    for e in (
        Extra(
            "perception",
            ("open3d",),
            "Open3D (perception from the cameras: TSDF fusion)",
            "only --perception gt runs without it, and only in simulation",
        ),
        Extra("report", ("matplotlib",), "matplotlib (reports' plots)"),
        Extra("record", ("mcap",), "mcap (MCAP recordings)"),
        Extra("video", ("imageio_ffmpeg",), "imageio-ffmpeg (videos)"),
        Extra("llama", ("llama_cpp",), "llama-cpp-python (local GGUF models in-process)"),
        Extra("ray", ("ray",), "Ray (sweeps and studies on a cluster)"),
        Extra("detectors", ("torch", "transformers"), "torch and transformers (open-vocabulary detectors)"),
        Extra("franky", ("franky",), "franky and franky-sim (the FR3 and Franka arms through libfranka)"),
        Extra("realsense", ("pyrealsense2",), "librealsense (RealSense cameras)"),
        Extra("menagerie", ("mujoco_menagerie",), "MuJoCo Menagerie (robot models downloaded on first use)"),
    )
}


def installed(name: str) -> bool:
    """Whether every module of the extra ``name`` can be imported (found, not imported: that can be slow)."""
    return all(_findable(module) for module in _extra(name).modules)


def _findable(module: str) -> bool:
    try:
        return importlib.util.find_spec(module) is not None
    except (ImportError, ValueError):  # a parent package that fails to import, or a module without a spec
        return False


def install_hint(name: str) -> str:
    """The command that installs the extra ``name`` here: ``.venv/bin/pip install -e '.[NAME]'`` in a clone set up
    by ``scripts/setup.sh`` (with the clone's and the environment's paths where the command is run elsewhere), and
    ``pip install 'roboscript[NAME]'`` where RoboScript was installed from a package."""
    _extra(name)
    root = source_checkout()
    if root is None:
        return f"{Path(sys.executable).parent / 'pip'} install 'roboscript[{name}]'"
    pip = Path(sys.executable).parent / "pip"
    here = Path.cwd().resolve()
    if root == here:
        shown_pip = _relative(pip, here)
        return f"{shown_pip} install -e '.[{name}]'"
    return f"{pip} install -e '{root}[{name}]'"


def _relative(path: Path, base: Path) -> str:
    try:
        return str(path.relative_to(base))
    except ValueError:
        return str(path)


def source_checkout() -> Path | None:
    """The clone RoboScript runs from (an editable install: ``src/roboscript`` beside a ``pyproject.toml``), or
    None for an installed package."""
    package = Path(__file__).resolve().parent
    root = package.parent.parent
    if package.parent.name == "src" and (root / "pyproject.toml").is_file():
        return root
    return None


def missing_text(name: str, needed_by: str) -> str:
    """What to say when ``needed_by`` (an option, a mode, a tool) needs the extra ``name`` and it is not installed."""
    extra = _extra(name)
    text = f"{needed_by} needs {extra.brings}, which is not installed; install it with: {install_hint(name)}"
    return f"{text} ({extra.without})" if extra.without else text


def missing(name: str, needed_by: str) -> MissingExtraError:
    """The error for ``needed_by`` when the extra ``name`` is not installed."""
    return MissingExtraError(missing_text(name, needed_by))


def require(name: str, needed_by: str) -> None:
    """Raises :class:`~roboscript.errors.MissingExtraError` if the extra ``name`` is not installed."""
    if not installed(name):
        raise missing(name, needed_by)


def _extra(name: str) -> Extra:
    try:
        return EXTRAS[name]
    except KeyError:
        raise ValueError(f"unknown extra {name!r}; extras: {', '.join(EXTRAS)}") from None
