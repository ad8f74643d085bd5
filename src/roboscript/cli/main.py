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
EXIT_STATUS = (
    "exit status: 0 when the command did what it was asked (exec, run, bench, demo: every trial passed its checks), "
    "1 when it ran and something failed (a task, a check, a robot's run), 2 for a usage error or a missing optional "
    "part; the --help of exec, run, bench and demo says what their 0 means"
)


class DefaultsShown(argparse.HelpFormatter):
    """Help that gives every option's default, where the option's own help does not already say it."""

    def _get_help_string(self, action: argparse.Action) -> str:
        text = action.help or ""
        quiet = action.default is None or action.default is False or action.default == argparse.SUPPRESS
        if quiet or "default" in text or "%(default)" in text or not action.option_strings:
            return text
        return text + " (default: %(default)s)"


class _Parser(argparse.ArgumentParser):
    def __init__(self, *args, **kwargs):
        kwargs.setdefault("formatter_class", DefaultsShown)
        super().__init__(*args, **kwargs)


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="roboscript", description=DESCRIPTION, epilog=EXIT_STATUS)
    parser.add_argument("--version", action="version", version=f"roboscript {version('roboscript')}")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
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
    from roboscript.cli.preflight import require_extras
    from roboscript.errors import RoboScriptError, error_message

    try:
        if hasattr(args, "perception"):
            resolve_perception(args)
        require_extras(args)
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
