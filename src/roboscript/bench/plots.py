"""Plots of benchmark runs and studies, drawn with matplotlib (the ``report`` extra) into PNG files.

Rates carry 95% Wilson intervals (:func:`roboscript.bench.stats.wilson_interval`): ten trials say little, and
the bars should show how little.
"""

from __future__ import annotations

import textwrap
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from roboscript import extras
from roboscript.bench.stats import wilson_interval

COLOURS = ["#4c72b0", "#dd8452", "#55a868", "#c44e52", "#8172b3", "#937860", "#da8bc3", "#8c8c8c"]


def _pyplot():
    try:
        import matplotlib
    except ImportError:
        raise extras.missing("report", "plots") from None
    matplotlib.use("Agg")  # files only: no display on a cluster node or in CI
    import matplotlib.pyplot as plt

    return plt


def _error_bars(successes: Sequence[int], trials: Sequence[int]) -> tuple[np.ndarray, np.ndarray]:
    rates = np.array([k / n if n else 0.0 for k, n in zip(successes, trials, strict=True)])
    bounds = np.array([wilson_interval(k, n) for k, n in zip(successes, trials, strict=True)]).reshape(-1, 2)
    return rates, np.clip(np.vstack([rates - bounds[:, 0], bounds[:, 1] - rates]), 0.0, None)


HORIZONTAL_FROM = 16  # groups from which bars lie sideways, a row per group (a study's 55 objects)


def grouped_bars(
    groups: Sequence[str],
    series: dict[str, tuple[Sequence[int], Sequence[int]]],
    path: str | Path,
    title: str,
    ylabel: str = "whole-task success",
    width_per_group: float = 0.8,
) -> Path:
    """Bars of success rates with 95% intervals: a group per label (a task, an object), a bar per series (a run,
    a template) in each; ``series[name] = (successes, trials)`` in the groups' order. Many groups are drawn as
    rows, top to bottom, so that every label stays readable."""
    plt = _pyplot()
    n = max(1, len(series))
    sideways = len(groups) >= HORIZONTAL_FROM or max(map(len, groups), default=0) > 30
    if sideways:
        longest = max(map(len, groups), default=0)
        size = (max(8.5, 5.5 + 0.09 * longest), max(4.0, 0.16 * len(groups) * max(1.0, n / 1.5) + 1.5))
    else:
        size = (max(6.0, 0.6 * len(groups) * max(1.0, n / 2) + 3), 4.2)
    fig, ax = plt.subplots(figsize=size)
    x = np.arange(len(groups))
    bar = width_per_group / n
    for i, (name, (successes, trials)) in enumerate(series.items()):
        rates, errors = _error_bars(successes, trials)
        style = {"label": f"{name} ({sum(successes)}/{sum(trials)})", "color": COLOURS[i % len(COLOURS)],
                 "error_kw": {"elinewidth": 0.8, "ecolor": "#333333"}, "capsize": 2}  # fmt: skip
        offsets = x + (i - (n - 1) / 2) * bar
        if sideways:
            ax.barh(offsets, rates, bar, xerr=errors, **style)
        else:
            ax.bar(offsets, rates, bar, yerr=errors, **style)
    if sideways:
        ax.set_yticks(x, groups, fontsize=7)
        ax.invert_yaxis()  # the first group on top
        ax.set_xlim(0, 1.05)
        ax.set_xlabel(ylabel)
        ax.grid(axis="x", alpha=0.3)
    else:
        crowded = len(groups) > 8 or sum(len(g) for g in groups) > 9 * size[0]
        ax.set_xticks(x, groups, rotation=50 if crowded else 0, ha="right" if crowded else "center", fontsize=8)
        ax.set_ylim(0, 1.05)
        ax.set_ylabel(ylabel)
        ax.grid(axis="y", alpha=0.3)
    if sideways:
        ax.set_ylim(len(groups) - 0.5, -0.5)  # no empty rows above and below
    ax.set_title(textwrap.fill(title, width=max(40, int(size[0] * 9))), fontsize=10)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), framealpha=0.9)
    fig.tight_layout()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110, bbox_inches="tight")  # labels and the legend outside the axes included
    plt.close(fig)
    return path
