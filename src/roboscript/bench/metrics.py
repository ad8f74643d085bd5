"""The four metrics of the benchmark over a task's trials."""

from __future__ import annotations

from collections.abc import Sequence

from roboscript.bench.trial import TrialRecord

METRICS = ("grammar_correctness", "semantic_correctness", "finished_steps_ratio", "whole_task_success")


def metrics(records: Sequence[TrialRecord]) -> dict[str, float]:
    """Grammar correctness: fraction of trials that ran without an exception. Semantic correctness: 1 if any
    trial passed every check. Finished-steps ratio: mean fraction of checks passed. Whole-task success: fraction
    of trials that passed every check."""
    if not records:
        return dict.fromkeys(METRICS, 0.0)
    n = len(records)
    ratios = [r.passed / len(r.checks) if r.checks else 0.0 for r in records]
    return {
        "grammar_correctness": round(sum(r.ok for r in records) / n, 4),
        "semantic_correctness": 1.0 if any(r.success for r in records) else 0.0,
        "finished_steps_ratio": round(sum(ratios) / n, 4),
        "whole_task_success": round(sum(r.success for r in records) / n, 4),
    }


def task_result(task: str, robot: str, records: Sequence[TrialRecord]) -> dict:
    """The object ``roboscript exec --json`` prints."""
    ordered = sorted(records, key=lambda r: r.trial)
    return {
        "task": task,
        "robot": robot,
        "trials": len(ordered),
        **metrics(ordered),
        "per_trial": [
            {
                "trial": r.trial,
                "seed": r.seed,
                "ok": r.ok,
                "outcome": r.outcome,
                "error": r.error,
                "repairs": r.repairs,
                "checks": r.checks,
                "sim_time_s": r.sim_time_s,
                "wall_time_s": r.wall_time_s,
                "judged_by": r.judged_by,
                "output": r.output,
            }
            for r in ordered
        ],
    }
