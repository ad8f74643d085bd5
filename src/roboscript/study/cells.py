"""A study's cells (template x object x grasp tool) written out as a suite of ordinary benchmark tasks.

Each cell becomes a task of a generated suite file, with a world file per template and object and a reference
program per cell, so that trials of a study run through the benchmark's own runner, records and resumption, on one
machine or on Ray (:mod:`roboscript.study.sweep`). The files are made again on every run; a file whose content is
unchanged is left as it is.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import yaml

from roboscript.bench.task_file import load_suite_file
from roboscript.codegen.prompt import task_query
from roboscript.errors import InvalidArgumentError
from roboscript.names import TABLE
from roboscript.study.study_file import Study, choose


@dataclass(frozen=True)
class Cell:
    """One cell of a study: a template, an object, a grasp tool. Its task id is ``template.object.grasp``."""

    template: str
    object: str
    grasp: str

    @property
    def task_id(self) -> str:
        return f"{self.template}.{self.object}.{self.grasp}"

    @staticmethod
    def from_task_id(task_id: str) -> Cell:
        parts = task_id.split(".")
        if len(parts) != 3:
            raise InvalidArgumentError(f"{task_id!r} is not a study cell's task id (template.object.grasp)")
        return Cell(*parts)


def select_cells(
    study: Study,
    templates: Sequence[str] | None = None,
    objects: Sequence[str] | None = None,
    grasps: Sequence[str] | None = None,
) -> list[Cell]:
    """The cells of ``study`` limited to the given templates, objects and grasp tools (all where None), in the
    study's order; an unknown name is a ``KeyError`` naming the valid ones."""
    chosen_templates = [t.id for t in study.templates] if templates is None else list(templates)
    chosen_objects = list(study.objects) if objects is None else list(objects)
    chosen_grasps = list(study.grasps) if grasps is None else list(grasps)
    for t in chosen_templates:
        study.template(t)
    for g in chosen_grasps:
        choose(study.grasps, g, "grasp tool")
    for o in chosen_objects:
        choose(dict.fromkeys(study.objects), o, "object of the study")
    return [Cell(t, o, g) for t in chosen_templates for o in chosen_objects for g in chosen_grasps]


def write_suite(study: Study, cells: Sequence[Cell], folder: str | Path) -> Path:
    """Writes the suite of ``cells`` into ``folder`` (its file, ``worlds/`` and the programs' folder) and returns
    the suite file's path, validated as any suite file is."""
    folder = Path(folder)
    programs = folder / study.name
    worlds = folder / "worlds"
    programs.mkdir(parents=True, exist_ok=True)
    worlds.mkdir(parents=True, exist_ok=True)
    tasks = []
    for cell in cells:
        template = study.template(cell.template)
        instruction, world, checks, program = template.instantiate(cell.object, study.grasps[cell.grasp])
        world_name = f"{cell.template}.{cell.object}"
        world = {"name": world_name, "description": f"study {study.name}: {instruction}", **world}
        _write(worlds / f"{world_name}.yaml", yaml.safe_dump(world, sort_keys=False))
        _write(programs / f"{cell.task_id}.py", program)
        names = [TABLE, *(f["name"] for f in world.get("furniture", [])), *(o["name"] for o in world["objects"])]
        tasks.append(
            {
                "id": cell.task_id,
                "world": f"worlds/{world_name}.yaml",
                "query": task_query(names + _parts_named(checks, names), instruction),
                "checks": checks,
            }
        )
    suite = {
        "suite": study.name,
        "description": f"Generated from {study.source}: {study.description}",
        "source": study.source,
        "tasks": tasks,
    }
    path = folder / f"{study.name}.yaml"
    _write(path, yaml.safe_dump(suite, sort_keys=False, width=200))
    load_suite_file(path)  # a template whose world or checks do not hold for some object fails here, naming it
    return path


def _parts_named(checks: list, names: list[str]) -> list[str]:
    """Furniture parts the checks name (``cabinet.drawer_1``), which the query then lists with the drawer's handle,
    as the original benchmark's queries list the parts a task is about."""
    parts = []
    for check in checks:
        for value in check.values():
            for name in value if isinstance(value, list) else [value]:
                if isinstance(name, str) and "." in name and name not in names + parts:
                    parts.append(name)
    handles = [p.replace("drawer_", "handle_").replace("door_", "handle_") for p in parts]
    return parts + [h for h in handles if h not in parts]


def _write(path: Path, text: str) -> None:
    if not path.is_file() or path.read_text() != text:
        path.write_text(text)
