"""The eight free-form tasks of the benchmark (DESIGN.md §5): world, instruction, and checks.

Some checks depend on the world as it starts (the plate that was empty, where the apple was), so a task builds
its checks from the ground truth at the start of each trial.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from importlib import resources

from roboscript.bench.checks import Check, at, inside, on
from roboscript.sim.ground_truth import GroundTruth


@dataclass(frozen=True)
class Task:
    id: str
    world: str
    instruction: str
    build_checks: Callable[[GroundTruth], list[Check]]

    def query(self, gt: GroundTruth, instruction: str | None = None) -> str:
        """The task query given to an LLM: ``objects = [...] ; # <instruction>`` (the task's own by default)."""
        return f"objects = {gt.world.entity_names(('object',))!r} ; # {instruction or self.instruction}"

    def reference_program(self) -> str:
        """The verified program for this task, written against the tool API only."""
        return resources.files("roboscript.bench.programs").joinpath(f"{self.id}.py").read_text()


def _empty_plate(gt: GroundTruth) -> str:
    plates = [e.name for e in gt.world.entities if e.kind == "object" and e.category == "plate"]
    occupied = set()
    for plate in plates:
        box = gt.box(plate)
        for other in gt.world.entity_names(("object",)):
            c = gt.box(other).center
            if other != plate and box.lower[0] < c[0] < box.upper[0] and box.lower[1] < c[1] < box.upper[1]:
                occupied.add(plate)
    empty = [p for p in plates if p not in occupied]
    if len(empty) != 1:
        raise ValueError(f"simple_1 needs exactly one empty plate; plates: {plates}, occupied: {sorted(occupied)}")
    return empty[0]


def _boxes(gt: GroundTruth) -> list[str]:
    return [e.name for e in gt.world.entities if e.kind == "object" and e.category == "box"]


FRUITS = ("apple", "banana", "lemon", "orange", "plum", "peach", "pear", "strawberry")


def _fruits(gt: GroundTruth) -> list[str]:
    return [e.name for e in gt.world.entities if e.kind == "object" and e.category in FRUITS]


def _table_objects(gt: GroundTruth, container: str) -> list[str]:
    return [n for n in gt.world.entity_names(("object",)) if n != container]


TASKS: dict[str, Task] = {
    t.id: t
    for t in [
        Task(
            "simple_0",
            "world_2_pick_and_place",
            "Place the apple into the footed bowl",
            lambda gt: [inside("apple", "footed_bowl")],
        ),
        Task(
            "simple_1",
            "world_3_mug_to_empty_plate",
            "Place the brown cup into an empty plate",
            lambda gt: [on("brown_cup", _empty_plate(gt))],
        ),
        Task(
            "moderate_0",
            "world_1_table_sort",
            "Open the second top cabinet drawer and place all boxes into it",
            lambda gt: [inside(b, "cabinet.drawer_1") for b in _boxes(gt)],
        ),
        Task(
            "moderate_1",
            "world_6_mug_to_same_color_plate",
            "Move the white mug into a container with the same color",
            lambda gt: [on("white_mug", "white_plate")],
        ),
        Task(
            "moderate_2",
            "world_5_mug_to_cabinet",
            "Place the mug into the second top drawer",
            lambda gt: [inside("mug", "cabinet.drawer_1")],
        ),
        Task(
            "hard_0",
            "world_1_table_sort",
            "Place all fruits on the table into the white plate",
            lambda gt: [on(f, "white_plate") for f in _fruits(gt)],
        ),
        Task(
            "hard_1",
            "world_1_table_sort",
            "Exchange the position of the apple and the banana on the table",
            lambda gt: [at("apple", gt.box("banana").center), at("banana", gt.box("apple").center)],
        ),
        Task(
            "hard_2",
            "world_4_clear_table_to_basket",
            "Clear the table by moving all table objects into the basket",
            lambda gt: [inside(o, "basket") for o in _table_objects(gt, "basket")],
        ),
    ]
}


def free_task(world: str, instruction: str | None) -> Task:
    """An instruction in any world (a name or a world file): nothing to check it against, so no checks."""
    if not instruction:
        raise ValueError(f"an instruction is needed to run in world {world!r} without a task")
    label = world.rsplit("/", 1)[-1].split(".", 1)[0]
    return Task(f"free:{label}", world, instruction, lambda gt: [])


def get_task(task_id: str) -> Task:
    if task_id not in TASKS:
        import difflib

        close = difflib.get_close_matches(task_id, TASKS, n=2)
        hint = f"; did you mean {' or '.join(close)}?" if close else ""
        raise KeyError(f"no task {task_id!r}{hint} Tasks: {', '.join(TASKS)}")
    return TASKS[task_id]
