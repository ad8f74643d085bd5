"""Makes OpenMP's worker threads sleep, not spin, while they wait for work, before any library starts them.

Open3D (TSDF fusion) and PyTorch (detectors) run their loops on OpenMP, whose threads by default spin for a while
after each parallel loop waiting for the next one. On a machine whose cores are all busy (benchmark trials run one
per core, a ROS twin runs beside its robot) the spinning threads take the cores from the threads they wait for:
fusing three views took 20 to 70 s there instead of 0.7 s. Passive waiting costs little when the machine is idle.
"""

from __future__ import annotations

import os

WAIT_POLICY = "OMP_WAIT_POLICY"


def calm_thread_pools() -> str:
    """Sets ``OMP_WAIT_POLICY=PASSIVE`` unless the user chose a policy; returns the policy in force. OpenMP reads it
    once, when its runtime loads, so this runs on importing :mod:`roboscript`, before Open3D or PyTorch."""
    return os.environ.setdefault(WAIT_POLICY, "PASSIVE")
