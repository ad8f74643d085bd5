"""Options and results that several commands share: the robot, the suite, perception, repair rounds, a task's result."""

from __future__ import annotations

import argparse
import os

# roboscript.robots.ROBOTS, named here so that --help imports no MuJoCo (a test holds the two equal)
ROBOT_NAMES = ("panda", "ur5e", "fr3")


def _whole_number(text: str, least: int, expected: str, refused: str) -> int:
    """``text`` as a whole number of at least ``least``; argparse's error names ``expected`` where it is not one
    and says ``refused <least> or more`` where it is too small."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected {expected}, got {text!r}") from None
    if value < least:
        raise argparse.ArgumentTypeError(f"{refused} {least} or more, got {value}")
    return value


def rounds(text: str) -> int:
    """``--repair``: a whole number of rounds, 0 or more."""
    return _whole_number(text, 0, "a whole number of rounds", "repair rounds must be")


def count(text: str) -> int:
    """``--trials``, ``--jobs``: a whole number, 1 or more."""
    return _whole_number(text, 1, "a whole number, 1 or more", "must be")


def seconds(text: str) -> float:
    """``--timeout``: a positive number of seconds."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number of seconds, got {text!r}") from None
    if not value > 0:
        raise argparse.ArgumentTypeError(f"must be a positive number of seconds, got {text}")
    return value


def add_run_options(parser: argparse.ArgumentParser, trials: int) -> None:
    from roboscript.bench.runner import default_jobs

    parser.add_argument("--robot", choices=ROBOT_NAMES, default="panda", help="the arm")
    parser.add_argument("--trials", type=count, default=trials, help="how many trials, each with its own seed")
    parser.add_argument("--seed", type=int, default=0, help="trial i uses seed + i for the world's randomisation")
    parser.add_argument("--timeout", type=seconds, default=300.0, help="time limit of one program, wall seconds")
    parser.add_argument(
        "--jobs", type=count, default=default_jobs(), help="trials run at once, one process each (default: the cores)"
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    add_perception_option(parser)
    add_suite_option(parser)


def add_suite_option(parser: argparse.ArgumentParser) -> None:
    from roboscript.bench.tasks import DEFAULT_SUITE, suite_names

    parser.add_argument(
        "--suite",
        type=_suite,
        default=DEFAULT_SUITE,
        help=f"the tasks' suite: {', '.join(suite_names())} (default {DEFAULT_SUITE}), or a suite file's path",
    )


def _suite(text: str) -> str:
    """``--suite``: a packaged suite's name, or a suite file's path (made absolute for the trial processes)."""
    from roboscript.bench.tasks import load_suite, suite_path
    from roboscript.datafile import names_a_file

    try:
        path = suite_path(text)
        load_suite(text)
    except (KeyError, ValueError) as exc:
        message = exc.args[0] if isinstance(exc, KeyError) and exc.args else str(exc)
        raise argparse.ArgumentTypeError(message) from None
    return str(path) if names_a_file(text) else text


def add_perception_option(parser: argparse.ArgumentParser) -> None:
    from roboscript.perception.modes import PERCEPTION_MODES

    modes = "; ".join(f"{m}: {what}" for m, what in PERCEPTION_MODES.items())
    modes += "; gt-2d, gt-3d and gt-scene combine with '+' (gt-2d+gt-scene)"
    parser.add_argument(
        "--perception",
        type=_perception_mode,
        default=None,
        metavar="MODE",
        help=modes + "; default: gt, or full with --backend ros or franky",
    )
    parser.add_argument(
        "--backend",
        choices=["mujoco", "ros", "franky"],
        default="mujoco",
        help="mujoco: the simulation in-process; ros: the world served by `roboscript ros-sim` on a master of the "
        "trial's own, the tools on the ROS backend, perception from the cameras and the segmentation topic; franky: "
        "the world served by franky-sim, its FR3 (--robot fr3) driven through libfranka, perception from the cameras",
    )
    parser.add_argument(
        "--robot-config",
        default=None,
        help="with --backend ros or franky: a robot configuration file or packaged name (default: the arm's "
        "packaged one)",
    )
    parser.add_argument(
        "--detector",
        default=None,
        metavar="KIND[:PATH]",
        help="the detector of modes without ground-truth 2D boxes: trained (the packaged model this project trains), "
        "trained:FILE.npz (from train-detector), owlv2:DIR or grounding-dino:DIR (DIR written by save_pretrained); "
        "default: $ROBOSCRIPT_DETECTOR, else trained",
    )


def _perception_mode(text: str):
    from roboscript.perception.modes import parse_mode

    try:
        return parse_mode(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def resolve_perception(args: argparse.Namespace) -> None:
    """The perception mode with its detector, from --detector or the environment: the one place either is read.
    A missing detector fails here, before any world is built."""
    from roboscript.perception.modes import DETECTOR_ENV, SEGMENTATION, perception_mode

    backend = getattr(args, "backend", "mujoco")
    on_robot = backend == "ros"
    mode = args.perception or ("full" if backend in ("ros", "franky") else "gt")
    # A robot served by ros-sim (or with a segmentation node) grounds phrases in its segmentation topic by default.
    detector = args.detector or os.environ.get(DETECTOR_ENV) or (SEGMENTATION if on_robot else None)
    args.perception = perception_mode(mode, detector)


RECORD_HELP = (
    "record the trial into this MCAP file for Foxglove: camera images, perceived boxes, planning scene, planned "
    "and executed paths, and every tool call with its answer (needs the record extra)"
)
