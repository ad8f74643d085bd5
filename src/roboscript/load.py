"""How busy the machine is: wall-clock time budgets scale by it before they call something too slow.

Machines are shared: a program that takes 60 s on an idle machine takes 120 s while another benchmark runs beside
it, and a time limit set for the idle machine would then fail a correct program.
"""

from __future__ import annotations

import os

MAX_FACTOR = 4.0  # a budget grows at most this much: an endless loop must still end


def load_factor(cap: float = MAX_FACTOR) -> float:
    """How many times longer work takes now than on an idle machine, as far as the load shows: the one-minute load
    average per CPU, at least 1, at most ``cap``."""
    try:
        load = os.getloadavg()[0]
    except OSError:  # no load average on this system
        return 1.0
    return float(min(cap, max(1.0, load / (os.cpu_count() or 1))))
