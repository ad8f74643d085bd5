"""A generated suite: template tasks over generated worlds, written as an ordinary suite file with its worlds and
oracle programs, so that ``roboscript bench --suite FILE`` runs it with the oracles as its reference policy.

Worlds take tasks from the families that fit them, the families used least so far first, so that every family is
well represented; each task's id is ``<family>.<world>``.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import yaml

from roboscript.bench.task_file import load_suite_file
from roboscript.codegen.prompt import task_query
from roboscript.errors import InvalidArgumentError
from roboscript.generate.families import FAMILIES, FIRST_FAMILIES, TemplateTask
from roboscript.generate.recipe import Recipe
from roboscript.generate.scene import Scene
from roboscript.generate.worlds import GeneratedWorld, generate_world, world_seed

TASKS_PER_WORLD = 4


@dataclass(frozen=True)
class GeneratedTask:
    """A template task in a generated world."""

    id: str
    world: GeneratedWorld
    task: TemplateTask

    @property
    def query(self) -> str:
        return task_query(self.world.spec.query_names(), self.task.instruction)


def world_tasks(
    world: GeneratedWorld, seed: int, used: Counter, families: Sequence[str], per_world: int = TASKS_PER_WORLD
) -> list[GeneratedTask]:
    """Up to ``per_world`` tasks of distinct families for ``world``, the least used families first (``used`` is
    updated); deterministic for the world and ``seed``."""
    rng = np.random.default_rng(np.random.SeedSequence([seed, world.seed[1], 7]))
    # Families added since version 1 draw their place in the order from a stream of their own: the draws of the
    # first nine, and so the tasks of the worlds a published suite already holds, stay as they were.
    later = np.random.default_rng(np.random.SeedSequence([seed, world.seed[1], 8]))
    keys = {f: rng.random() for f in families if f in FIRST_FAMILIES}
    keys.update({f: later.random() for f in families if f not in FIRST_FAMILIES})
    scene = Scene(world.spec)
    order = sorted(families, key=lambda f: (used[f], keys[f]))
    tasks = []
    for family in order:
        task = FAMILIES[family](scene, rng)
        if task is None:
            continue
        used[family] += 1
        tasks.append(GeneratedTask(f"{task.family}.{world.name}", world, task))
        if len(tasks) == per_world:
            break
    return tasks


def generate_tasks(
    recipe: Recipe,
    worlds: int,
    seed: int,
    families: Sequence[str] | None = None,
    per_world: int = TASKS_PER_WORLD,
    prefix: str = "gen",
    more: Sequence[tuple[Recipe, int]] = (),
) -> list[GeneratedTask]:
    """Tasks of the chosen families (all where None) over ``worlds`` worlds of ``recipe``, then over the worlds of
    each of ``more``'s ``(recipe, count)``, numbered on (a suite's worlds of doors after its tabletops)."""
    families = list(families or FAMILIES)
    for family in families:
        if family not in FAMILIES:
            raise KeyError(f"unknown task family {family!r}; families: {', '.join(FAMILIES)}")
    used: Counter = Counter()
    tasks: list[GeneratedTask] = []
    plan = [recipe] * worlds + [r for r, count in more for _ in range(count)]
    for index, made_by in enumerate(plan):
        world = generate_world(made_by, seed, index, f"{prefix}_{index:03d}")
        tasks += world_tasks(world, seed, used, families, per_world)
    return tasks


# The template suites' version (docs/generation.md lists what each changed): 2 fixed three sorting tasks' checks to
# what their words select, 3 added worlds of a cupboard and the families that open its door and close its drawers,
# 4 worlds of a cupboard facing the robot and the family that puts things behind its door, 5 measures ``in`` in
# the receptacle's own axes, 6 checks what the words imply stays as it was (:mod:`roboscript.generate.stays`); the
# worlds, ids and instructions of earlier versions are kept.
SUITE_VERSION = 6


def write_suite(tasks: Sequence[GeneratedTask], folder: str | Path, name: str, description: str) -> Path:
    """Writes the suite file ``<folder>/<name>.yaml``, its worlds (``<folder>/<name>/worlds/``) and the oracle
    programs (``<folder>/<name>/<id>.py``); returns the suite file's path, loaded back and validated."""
    if not tasks:
        raise InvalidArgumentError("no tasks to write: no family fits the generated worlds")
    folder = Path(folder)
    programs = folder / name
    worlds = programs / "worlds"
    worlds.mkdir(parents=True, exist_ok=True)
    entries = []
    for task in tasks:
        _write(worlds / f"{task.world.name}.yaml", task.world.yaml())
        _write(programs / f"{task.id}.py", task.task.program)
        entries.append(
            {
                "id": task.id,
                "label": task.task.family,
                "world": f"{name}/worlds/{task.world.name}.yaml",
                "query": task.query,
                "checks": [dict(c) for c in task.task.checks],
            }
        )
    suite = {"suite": name, "version": SUITE_VERSION, "description": description, "tasks": entries}
    path = folder / f"{name}.yaml"
    _write(path, yaml.safe_dump(suite, sort_keys=False, width=200))
    load_suite_file(path)
    return path


def _write(path: Path, text: str) -> None:
    if not path.is_file() or path.read_text() != text:
        path.write_text(text)


__all__ = ["SUITE_VERSION", "GeneratedTask", "generate_tasks", "world_seed", "world_tasks", "write_suite"]
