"""The benchmark's task suites: packaged suite files (``roboscript/suites/*.yaml``) or any suite file by path.

``paper`` (the default) is the RoboScript paper's benchmark verbatim: its six worlds with its objects and names, its
queries character for character and its eval items as checks. ``cluttered`` holds the same eight tasks in busier
worlds with other objects and shortened instructions. The format is :mod:`roboscript.bench.task_file`.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from roboscript.bench.task_file import Task, TaskFileError, load_suite_file
from roboscript.codegen.prompt import task_query
from roboscript.datafile import PackagedFiles
from roboscript.errors import InvalidArgumentError, UnknownNameError, did_you_mean
from roboscript.sim.world_catalog import load_world

DEFAULT_SUITE = "paper"
FREE_SUITE = "free"
LISTED_TASKS = 20  # a suite with more tasks than this is not listed whole in an error


SUITES = PackagedFiles("suites", "suite", others="or a suite file's path")


def suite_names() -> list[str]:
    """The packaged suites, the default first."""
    return sorted(SUITES.names(), key=lambda n: n != DEFAULT_SUITE)


def suite_path(suite: str) -> Path:
    """The file of a packaged suite, or ``suite`` itself when it is a suite file's path."""
    return SUITES.path(suite, suite_names()).resolve()


@lru_cache(maxsize=16)
def _load(path: Path) -> dict[str, Task]:
    return {t.id: t for t in load_suite_file(path)}


def load_suite(suite: str = DEFAULT_SUITE) -> dict[str, Task]:
    """The tasks of ``suite`` (a packaged suite's name, or a suite file's path) by id, in the file's order."""
    path = suite_path(suite)
    tasks = _load(path)
    named = next(iter(tasks.values())).suite
    if path.parent == SUITES.directory().resolve() and named != path.stem:
        raise TaskFileError(str(path), "suite", f"names suite {named!r}; a packaged suite's file is named after it")
    return tasks


def get_task(task_id: str, suite: str = DEFAULT_SUITE) -> Task:
    """Task ``task_id`` of ``suite``; ``KeyError`` with the closest ids, and the suite's ids where they are few
    (else how many there are and how to list them)."""
    tasks = load_suite(suite)
    if task_id not in tasks:
        close = did_you_mean(task_id, tasks, n=2, cutoff=0.6)
        hint = f"; {close} " if close else ". "
        if len(tasks) <= LISTED_TASKS:
            listing = f"Tasks: {', '.join(tasks)}"
        else:
            listing = f"The suite has {len(tasks)} tasks: `roboscript tasks --suite {suite}` lists them"
        raise UnknownNameError(f"no task {task_id!r} in suite {suite!r}{hint}{listing}")
    return tasks[task_id]


def free_task(world: str, instruction: str | None) -> Task:
    """An instruction in any world (a name or a world file): nothing to check it against, so no checks. Its query
    lists every name of the world."""
    if not instruction:
        raise InvalidArgumentError(f"an instruction is needed to run in world {world!r} without a task")
    label = world.rsplit("/", 1)[-1].split(".", 1)[0]
    query = task_query(load_world(world).query_names(), instruction)
    return Task(f"free:{label}", FREE_SUITE, world, query, ())
