"""A study's results: success per object, template and grasp tool with 95% intervals, per shape class, and why
trials failed; as JSON, CSV and markdown in the paper's layout (objects as rows, templates as columns)."""

from __future__ import annotations

import csv
import io
from collections import Counter, defaultdict
from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass, field

from roboscript.bench.stats import wilson_interval
from roboscript.bench.trial import TrialRecord
from roboscript.objects import get_object_type
from roboscript.study.cells import Cell


@dataclass
class CellResult:
    """The trials of one cell on one robot."""

    robot: str
    template: str
    object: str
    grasp: str
    shape: str
    trials: int = 0
    successes: int = 0
    outcomes: dict[str, int] = field(default_factory=dict)
    errors: dict[str, int] = field(default_factory=dict)  # the kind of error that stopped a program
    trial_wall_s: float = 0.0  # the trials' own wall times added up

    @property
    def rate(self) -> float:
        return self.successes / self.trials if self.trials else 0.0

    @property
    def interval(self) -> tuple[float, float]:
        return wilson_interval(self.successes, self.trials)

    def to_dict(self) -> dict:
        low, high = self.interval
        return {**asdict(self), "rate": round(self.rate, 4), "ci95": [round(low, 4), round(high, 4)]}


def failure_kind(record: TrialRecord) -> str:
    """Why a trial failed, in a few words: the exception's class (``GraspError``), or ``checks failed: in``
    with the kinds of the checks that did not pass when the program ran to its end."""
    if record.success:
        return "success"
    if record.error:
        head = record.error.split(":", 1)[0].strip()
        return head if head.isidentifier() else record.outcome
    failed = sorted({c["check"].split("(", 1)[0] for c in record.checks if not c["passed"]})
    return "checks failed: " + ", ".join(failed) if failed else record.outcome


def cell_results(records: Iterable[TrialRecord], cells: Sequence[Cell]) -> list[CellResult]:
    """One result per cell and robot that has records, in the cells' order."""
    order = {c.task_id: i for i, c in enumerate(cells)}
    grouped: dict[tuple[str, str], list[TrialRecord]] = defaultdict(list)
    for r in records:
        if r.task in order:
            grouped[(r.robot, r.task)].append(r)
    results = []
    for (robot, task), rs in sorted(grouped.items(), key=lambda kv: (kv[0][0], order[kv[0][1]])):
        cell = Cell.from_task_id(task)
        result = CellResult(robot, cell.template, cell.object, cell.grasp, get_object_type(cell.object).shape)
        result.trials = len(rs)
        result.successes = sum(r.success for r in rs)
        result.outcomes = dict(Counter(r.outcome for r in rs).most_common())
        result.errors = dict(Counter(failure_kind(r) for r in rs if not r.success).most_common())
        result.trial_wall_s = round(sum(r.wall_time_s for r in rs), 3)
        results.append(result)
    return results


def _columns(results: Sequence[CellResult]) -> list[tuple[str, str]]:
    seen: dict[tuple[str, str], None] = {}
    for r in results:
        seen.setdefault((r.template, r.grasp), None)
    return list(seen)


def _cell(result: CellResult | None) -> str:
    if result is None or not result.trials:
        return "-"
    return f"{result.successes}/{result.trials}"


def object_table(results: Sequence[CellResult], robot: str) -> str:
    """The paper's layout: a row per object (grouped by shape), a column per template and grasp tool, each cell
    ``successes/trials``; then the rate of each column over all objects with its 95% interval."""
    mine = [r for r in results if r.robot == robot]
    columns = _columns(mine)
    by_key = {(r.object, r.template, r.grasp): r for r in mine}
    objects = list(dict.fromkeys(r.object for r in sorted(mine, key=lambda r: r.shape)))
    header = "| Object | Shape | " + " | ".join(f"{t} ({g})" for t, g in columns) + " |"
    lines = [header, "|---|---|" + "---|" * len(columns)]
    for obj in objects:
        shape = get_object_type(obj).shape
        cells = [_cell(by_key.get((obj, t, g))) for t, g in columns]
        lines.append(f"| {obj} | {shape} | " + " | ".join(cells) + " |")
    totals = []
    for t, g in columns:
        rs = [r for r in mine if (r.template, r.grasp) == (t, g)]
        k, n = sum(r.successes for r in rs), sum(r.trials for r in rs)
        low, high = wilson_interval(k, n)
        totals.append(f"**{k / max(n, 1):.2f}** [{low:.2f}, {high:.2f}]")
    lines.append("| **All objects** | | " + " | ".join(totals) + " |")
    return "\n".join(lines) + "\n"


def shape_table(results: Sequence[CellResult], robot: str) -> str:
    """Success rate per shape class (rows) and template and grasp tool (columns), with the objects counted."""
    mine = [r for r in results if r.robot == robot]
    columns = _columns(mine)
    shapes = sorted({r.shape for r in mine})
    lines = [
        "| Shape | Objects | " + " | ".join(f"{t} ({g})" for t, g in columns) + " |",
        "|---|---|" + "---|" * len(columns),
    ]
    for shape in shapes:
        count = len({r.object for r in mine if r.shape == shape})
        cells = []
        for t, g in columns:
            rs = [r for r in mine if r.shape == shape and (r.template, r.grasp) == (t, g)]
            k, n = sum(r.successes for r in rs), sum(r.trials for r in rs)
            cells.append(f"{k / n:.2f} ({k}/{n})" if n else "-")
        lines.append(f"| {shape} | {count} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def failure_table(results: Sequence[CellResult], robot: str) -> str:
    """Why trials failed, per template and grasp tool: each kind of failure with its count and the objects."""
    mine = [r for r in results if r.robot == robot]
    lines = ["| Template (grasp) | Failure | Trials | Objects |", "|---|---|---|---|"]
    for t, g in _columns(mine):
        kinds: dict[str, Counter] = defaultdict(Counter)
        for r in mine:
            if (r.template, r.grasp) != (t, g):
                continue
            for kind, count in r.errors.items():
                kinds[kind][r.object] += count
        for kind, objects in sorted(kinds.items(), key=lambda kv: -sum(kv[1].values())):
            names = ", ".join(f"{o} {c}" for o, c in objects.most_common())
            lines.append(f"| {t} ({g}) | {kind} | {sum(objects.values())} | {names} |")
    if len(lines) == 2:
        return "No trial failed.\n"
    return "\n".join(lines) + "\n"


def study_markdown(name: str, results: Sequence[CellResult], wall_time_s: float | None = None) -> str:
    """The study's report: per robot, the object table, the shape table and the failure breakdown."""
    out = [f"# Study `{name}`", ""]
    if wall_time_s is not None:
        out += [f"This session ran for {wall_time_s:.0f} s (a resumed study counts only what it ran itself).", ""]
    for robot in sorted({r.robot for r in results}):
        mine = [r for r in results if r.robot == robot]
        trials, wall = sum(r.trials for r in mine), sum(r.trial_wall_s for r in mine)
        out += [
            f"## {robot}",
            "",
            f"{trials} trials in {len(mine)} cells; the trials' own wall times add up to {wall:.0f} s "
            f"(the median cell's trials took {_median_trial(mine):.1f} s each).",
            "",
            "Successful trials per object (rows, grouped by shape) and template with its grasp tool (columns); the",
            "last row is each column's success rate over all objects with its 95% Wilson interval.",
            "",
            object_table(results, robot),
            "### By shape",
            "",
            shape_table(results, robot),
            "### Why trials failed",
            "",
            failure_table(results, robot),
        ]
    return "\n".join(out)


def _median_trial(results: Sequence[CellResult]) -> float:
    per_cell = sorted(r.trial_wall_s / r.trials for r in results if r.trials)
    return per_cell[len(per_cell) // 2] if per_cell else 0.0


def study_csv(results: Sequence[CellResult]) -> str:
    out = io.StringIO()
    writer = csv.writer(out)
    writer.writerow(["robot", "template", "object", "grasp", "shape", "trials", "successes", "rate", "ci95_low",
                     "ci95_high", "failures"])  # fmt: skip
    for r in results:
        low, high = r.interval
        failures = "; ".join(f"{k} {v}" for k, v in r.errors.items())
        writer.writerow(
            [r.robot, r.template, r.object, r.grasp, r.shape, r.trials, r.successes, f"{r.rate:.4f}",
             f"{low:.4f}", f"{high:.4f}", failures]
        )  # fmt: skip
    return out.getvalue()
