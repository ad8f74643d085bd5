"""Verified data sets of (query, world, program): template tasks over generated worlds, each program run in
simulation against its task's checks, and only those that passed kept.

``generate_dataset`` writes the tasks as a suite (:mod:`roboscript.generate.suite`), runs it with the benchmark's
runner under any policy (the oracle programs, or an LLM that writes its own from the query), and exports the
trials that passed every check as JSON lines (``dataset.jsonl``) beside the world files they name. The benchmark's
run directory is kept: an interrupted data set resumes where it stopped. The record format is
``dataset.schema.json`` (a JSON Schema) and docs/generation.md.
"""

from __future__ import annotations

import json
import shutil
from collections.abc import Sequence
from dataclasses import asdict, dataclass
from importlib import resources
from pathlib import Path

from roboscript.bench.benchmark import policy_llm, run_benchmark
from roboscript.bench.results import read_records
from roboscript.bench.tasks import load_suite
from roboscript.bench.trial import TrialRecord
from roboscript.generate.recipe import Recipe
from roboscript.generate.suite import generate_tasks, write_suite

FORMAT = "roboscript-dataset/1"
SUITE_NAME = "dataset"


@dataclass(frozen=True)
class DatasetRecord:
    """One verified example: the query a model is given, the world it acts in, the program and what it did."""

    format: str
    id: str
    family: str
    query: str
    instruction: str
    world: str  # a world file, relative to the data set's folder
    program: str
    program_source: str  # "oracle" or the LLM spec that wrote it
    robot: str
    seed: int
    outcome: str
    checks: list[dict]
    verified: bool  # every check passed in simulation
    sim_time_s: float

    def to_json(self) -> str:
        return json.dumps(asdict(self), ensure_ascii=False)


def schema() -> dict:
    """The JSON Schema of a data set's records."""
    return json.loads((resources.files("roboscript") / "generate" / "dataset.schema.json").read_text())


def export_records(suite_file: Path, records: Sequence[TrialRecord], policy: str, out: Path) -> list[DatasetRecord]:
    """The records of trials that passed every check, with their world files copied under ``out/worlds``;
    written to ``out/dataset.jsonl`` (replacing it), and returned."""
    tasks = load_suite(str(suite_file))
    llm = policy_llm(policy)
    worlds = out / "worlds"
    worlds.mkdir(parents=True, exist_ok=True)
    order = {task_id: k for k, task_id in enumerate(tasks)}
    copied: set[str] = set()
    kept = []
    for record in sorted(records, key=lambda r: (order.get(r.task, len(order)), r.robot, r.trial)):
        if not (record.ok and record.success):
            continue
        task = tasks[record.task]
        world_file = Path(task.world)
        if world_file.name not in copied:  # several records share a world
            shutil.copyfile(world_file, worlds / world_file.name)
            copied.add(world_file.name)
        program = record.program if llm is not None else task.reference_program()
        kept.append(
            DatasetRecord(
                format=FORMAT,
                id=f"{record.task}.{record.robot}.{record.trial}",
                family=task.label,
                query=task.query,
                instruction=task.instruction,
                world=f"worlds/{world_file.name}",
                program=program or "",
                program_source=llm or "oracle",
                robot=record.robot,
                seed=record.seed,
                outcome=record.outcome,
                checks=[dict(c) for c in record.checks],
                verified=True,
                sim_time_s=round(record.sim_time_s, 3),
            )
        )
    path = out / "dataset.jsonl"
    tmp = path.with_suffix(".jsonl.tmp")
    tmp.write_text("".join(r.to_json() + "\n" for r in kept))
    tmp.replace(path)
    return kept


@dataclass(frozen=True)
class DatasetOutcome:
    records: list[DatasetRecord]
    trials: int
    path: Path
    wall_time_s: float


def generate_dataset(
    recipe: Recipe,
    worlds: int,
    seed: int,
    out: str | Path,
    policy: str = "reference",
    robot: str = "panda",
    jobs: int = 1,
    families: Sequence[str] | None = None,
    per_world: int = 4,
    timeout: float = 300.0,
    progress: bool = True,
) -> DatasetOutcome:
    """Generates ``worlds`` worlds and their template tasks, runs each task once under ``policy`` (``reference``:
    the oracle programs; ``llm:SPEC``: programs an LLM writes) and exports the verified ones into ``out``."""
    policy_llm(policy)  # an unknown policy fails here, before anything is generated
    out = Path(out)
    tasks = generate_tasks(recipe, worlds, seed, families, per_world)
    description = f"Template tasks over {worlds} worlds of recipe {recipe.name!r}, seed {seed}."
    suite_file = write_suite(tasks, out / "suite", SUITE_NAME, description)
    result = run_benchmark(
        policy,
        None,
        robot,
        1,
        seed,
        out / "run",
        jobs,
        timeout=timeout,
        progress=progress,
        suite=str(suite_file),
    )
    records = read_records(Path(result["out"]) / "results.jsonl")
    kept = export_records(suite_file, records, policy, out)
    return DatasetOutcome(kept, len(records), out / "dataset.jsonl", result["wall_time_s"])
