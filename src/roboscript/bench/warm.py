"""Warms the process that trials are forked from, as a side effect of importing this module.

MuJoCo keeps the meshes it has decoded in a process-wide asset cache, and the robots' meshes are most of what
compiling a world costs: about 4 s for the Panda's the first time in a process, a third of a second for a whole
world after. The trial fork server (:func:`roboscript.bench.runner.trial_context`) imports this module, so every
trial forked from it starts with the cache warm.

Open3D, which observed perception fuses views with, takes seconds to import (it brings scikit-learn along); it is
imported here once, where it is installed, instead of in every trial that looks. So are the modules every trial
imports only once it runs (the assembly of the tools, perception, OMPL): a tenth to a fifth of a second each time.
"""

from __future__ import annotations

import contextlib
import ctypes
import importlib
import importlib.util
import os

from roboscript.geometry import Transform
from roboscript.robots import ROBOTS
from roboscript.robots.assets import AssetNotFoundError
from roboscript.robots.mujoco_model import RobotModel

# What a trial imports as it runs, in any perception mode (found by comparing sys.modules before and after).
TRIAL_MODULES = (
    "roboscript.assembly",
    "roboscript.perception.ground_truth",
    "roboscript.perception.pipeline",
    "roboscript.planning.ground_truth_scene",
    "roboscript.planning.perceived_scene",
)
OMP_THREADS = "OMP_NUM_THREADS"
OPENMP_LIBRARY = "libgomp.so.1"  # the GNU OpenMP runtime Open3D's wheel links (scikit-learn's own copy is renamed)


def warm_robot_meshes() -> None:
    """Compiles each robot once, alone, so that its meshes are in MuJoCo's asset cache. An optional arm whose model
    is not installed is left out: a trial on it fails with the error that says how to install it."""
    for description in ROBOTS.values():
        try:
            RobotModel(description, Transform.identity())
        except AssetNotFoundError:
            continue


def import_trial_modules() -> None:
    """Imports what trials import as they run, OMPL with its logging set as the planner sets it."""
    for name in TRIAL_MODULES:
        importlib.import_module(name)
    from roboscript.planning.planner import import_ompl

    import_ompl()


def import_open3d() -> bool:
    """Imports Open3D where it is installed (the ``perception`` extra); returns whether it was.

    Open3D's library starts OpenMP's thread team as it loads, and a team does not survive a fork: a forked trial
    that fuses views waits forever for threads it does not have. So OpenMP is loaded here with one thread (no team
    is started), and each forked trial sets the number of threads it would have had (see :func:`_after_fork`).
    SciPy and scikit-learn are imported first, outside that setting, so that their BLAS keeps its threads."""
    if importlib.util.find_spec("open3d") is None:
        return False
    import scipy.linalg  # noqa: F401
    import sklearn  # noqa: F401

    chosen = os.environ.get(OMP_THREADS)
    os.environ[OMP_THREADS] = "1"
    try:
        import open3d  # noqa: F401
    finally:
        if chosen is None:
            del os.environ[OMP_THREADS]
        else:
            os.environ[OMP_THREADS] = chosen
    os.register_at_fork(after_in_child=_after_fork)
    return True


def _after_fork() -> None:
    """In a forked trial: OpenMP's threads as many as the user chose, else as many as this process may use."""
    chosen = os.environ.get(OMP_THREADS, "")
    threads = int(chosen) if chosen.isdigit() and int(chosen) > 0 else len(os.sched_getaffinity(0))
    # Another OpenMP runtime than GNU's: the trial fuses on one thread, slower but sound.
    with contextlib.suppress(OSError, AttributeError):
        ctypes.CDLL(OPENMP_LIBRARY).omp_set_num_threads(threads)


warm_robot_meshes()
import_open3d()  # first: its OpenMP must be loaded the way import_open3d says, whoever imports it
import_trial_modules()
