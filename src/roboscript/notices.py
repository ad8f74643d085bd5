"""Notices a tool gives about what it did on the program's behalf ("backed off 3 cm of 6 cm: the rest is out of
reach"): logged on the ``roboscript.notices`` logger, and shown in the program's own output.

A tool calls :func:`notice`; whoever runs the tool for a program collects what was noticed during the call with
:func:`collected` and hands it to the program's side, which writes it into the program's output as
``[notice] ...`` lines. Nothing is printed: a command's stdout carries its own output alone.
"""

from __future__ import annotations

import contextlib
import logging
from collections.abc import Iterator

LOGGER = logging.getLogger("roboscript.notices")
PREFIX = "[notice] "  # how a notice's line begins in the program's output
MAX_NOTICE = 500  # characters of one notice
MAX_NOTICES = 20  # notices kept from one tool call


def notice(text: str) -> None:
    """Tells the program (and the log) what a tool did on its behalf."""
    LOGGER.info(text[:MAX_NOTICE])


class _Collector(logging.Handler):
    def __init__(self):
        super().__init__(logging.INFO)
        self.texts: list[str] = []

    def emit(self, record: logging.LogRecord) -> None:
        if len(self.texts) < MAX_NOTICES:
            self.texts.append(record.getMessage()[:MAX_NOTICE])


def notice_line(text: str) -> str:
    """A notice as a line of the program's output."""
    return f"{PREFIX}{text}\n"


def split_output(output: str) -> tuple[list[str], list[str]]:
    """A program's output as the lines it printed and the notices the tools gave (without their prefix)."""
    printed, notices = [], []
    for line in output.splitlines():
        if line.startswith(PREFIX):
            notices.append(line[len(PREFIX) :])
        else:
            printed.append(line)
    while printed and not printed[-1].strip():
        printed.pop()
    return printed, notices


@contextlib.contextmanager
def collected() -> Iterator[list[str]]:
    """The notices given while the block runs, in order (at most :data:`MAX_NOTICES`)."""
    collector = _Collector()
    LOGGER.addHandler(collector)
    level = LOGGER.level
    if LOGGER.getEffectiveLevel() > logging.INFO:
        LOGGER.setLevel(logging.INFO)
    try:
        yield collector.texts
    finally:
        LOGGER.removeHandler(collector)
        LOGGER.setLevel(level)
