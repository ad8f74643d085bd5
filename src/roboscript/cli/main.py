"""The ``roboscript`` command."""

from __future__ import annotations

import argparse
import os
import signal
import sys
import threading
from importlib.metadata import version

from roboscript.cli.catalog import add_catalog_commands
from roboscript.cli.detector import add_detector_commands
from roboscript.cli.generate import add_generate_commands
from roboscript.cli.options import ROBOT_NAMES, resolve_perception
from roboscript.cli.robot import add_replay_command, add_ros_sim_command
from roboscript.cli.runs import add_run_commands
from roboscript.cli.studies import add_study_commands

DESCRIPTION = (
    "RoboScript: instructions in words to robot motion. An LLM writes a program against the tool API "
    "(`roboscript tools`), which is checked, run in a sandbox against a simulated or a real arm, and judged."
)


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="roboscript", description=DESCRIPTION)
    parser.add_argument("--version", action="version", version=f"roboscript {version('roboscript')}")
    sub = parser.add_subparsers(dest="command", required=True)
    add_catalog_commands(sub)
    add_run_commands(sub)
    add_ros_sim_command(sub)
    add_replay_command(sub)
    add_study_commands(sub)
    add_generate_commands(sub, ROBOT_NAMES)
    add_detector_commands(sub)
    return parser


def _exit_on_sigterm(signum, frame) -> None:
    # SystemExit unwinds like Ctrl-C does, so running trials are stopped and results written so far are kept.
    sys.exit(128 + signum)


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if (
        args.command in ("exec", "run", "bench", "sweep", "study", "generate")
        and threading.current_thread() is threading.main_thread()
    ):
        signal.signal(signal.SIGTERM, _exit_on_sigterm)
    from roboscript.errors import RoboScriptError, error_message

    try:
        if hasattr(args, "perception"):
            resolve_perception(args)
        return args.func(args)
    except (RoboScriptError, KeyError, ValueError) as exc:  # the builtins: argument checks in the commands
        print(f"roboscript: error: {error_message(exc)}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # the reader went away (`roboscript objects | head`): stop quietly, as a pipe's writer does
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())  # what is still buffered must not fail again at exit
        return 128 + signal.SIGPIPE


if __name__ == "__main__":
    sys.exit(main())
