"""What a command checks before its first trial: that the optional parts its options need are installed. A missing
one is then a usage error that says how to install it, not a traceback inside every trial."""

from __future__ import annotations

import argparse

from roboscript import extras
from roboscript.perception.detection.detectors import DETECTOR_KINDS
from roboscript.perception.modes import PerceptionMode


def needed_extras(args: argparse.Namespace) -> list[tuple[str, str]]:
    """The extras the options of ``args`` need, each with the option that needs it."""
    needed = []
    backend = getattr(args, "backend", "mujoco")
    mode = getattr(args, "perception", None)  # resolved into a PerceptionMode by then
    if isinstance(mode, PerceptionMode):
        if mode.uses_cameras(simulated=backend == "mujoco"):
            on = "" if backend == "mujoco" else f" on --backend {backend}"
            needed.append(("perception", f"--perception {mode}{on}"))
        if mode.needs_detector and mode.detector is not None and mode.detector.kind in DETECTOR_KINDS:
            needed.append(("detectors", f"--detector {mode.detector}"))
    if getattr(args, "record", None):
        needed.append(("record", "--record"))
    if getattr(args, "video", None) or getattr(args, "videos", "none") != "none":
        needed.append(("video", "--video" if getattr(args, "video", None) else "--videos"))
    if backend == "franky":
        needed.append(("franky", "--backend franky"))
    for spec in _llm_specs(args):
        needed += [(extra, f"the LLM {spec}") for extra in _llm_extras(spec)]
    return needed


def _llm_specs(args: argparse.Namespace) -> list[str]:
    specs = []
    if getattr(args, "llm", None):
        specs.append(args.llm)
    policy = getattr(args, "policy", None)
    if isinstance(policy, str) and policy.startswith("llm:"):
        specs.append(policy[4:])
    return specs


def _llm_extras(spec: str) -> list[str]:
    kind, _, rest = spec.partition(":")
    if kind == "llama":
        return ["llama"]
    if kind in ("record", "cache") and "=" in rest:
        return _llm_extras(rest.partition("=")[2])
    return []


def require_extras(args: argparse.Namespace) -> None:
    """Raises :class:`~roboscript.errors.MissingExtraError` for the first extra the options need that is not
    installed."""
    for extra, needed_by in needed_extras(args):
        extras.require(extra, needed_by)
