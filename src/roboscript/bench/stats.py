"""Confidence intervals for success rates over a few trials."""

from __future__ import annotations

import math

from roboscript.errors import InvalidArgumentError

Z95 = 1.959964  # the standard normal's 97.5% quantile: a two-sided 95% interval


def wilson_interval(successes: int, trials: int, z: float = Z95) -> tuple[float, float]:
    """The Wilson score interval of a binomial proportion (95% by default): unlike the normal approximation it
    stays within [0, 1] and is not empty at 0/n or n/n, which is where a benchmark's rates often are."""
    if trials <= 0:
        return (0.0, 1.0)
    if not 0 <= successes <= trials:
        raise InvalidArgumentError(f"successes must be within 0..{trials}, got {successes}")
    p = successes / trials
    denominator = 1 + z * z / trials
    centre = (p + z * z / (2 * trials)) / denominator
    half = z * math.sqrt(p * (1 - p) / trials + z * z / (4 * trials * trials)) / denominator
    return (max(0.0, centre - half), min(1.0, centre + half))
