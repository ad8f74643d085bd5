"""OMPL's PRM and PRM* run in the calling thread alone.

``PRM::solve`` grows the roadmap in the calling thread and starts a second thread (``checkForSolution``) that adds
the goal states after the first to the roadmap, each under the roadmap's lock and with motion checks, and looks for
a path. Here the state validity checker is Python, and the bindings (nanobind) keep the GIL through ``solve``:
that thread waits for the GIL inside a motion check while holding the roadmap's lock, and the calling thread,
holding the GIL, waits for that lock to add its next milestone. The process then hangs with the CPU idle (seen
with a UR5e, whose goals come with their whole-turn equivalents); the two threads can also run the checker at once
on the one MuJoCo scene (seen as a segmentation fault).

So ``solve`` is never called: the roadmap is grown by PRM's own ``growRoadmap`` and ``expandRoadmap``, two parts
growing to one expanding as in ``PRM::constructRoadmap``, in slices of time, and between slices the query is
answered here: the start and the goals are connected to their nearest milestones with PRM's connection strategy
(the 10 nearest for PRM, ``ceil((e + e / dof) ln n)`` for PRM*), and the shortest path runs through the roadmap's
edges, the weights of which are PRM's path-length costs.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import dijkstra

PRM_NEIGHBORS = 10  # OMPL's magic::DEFAULT_NEAREST_NEIGHBORS
BUILD_TIME = 0.2  # OMPL's magic::ROADMAP_BUILD_TIME: the longest expansion slice, growth slices are twice as long
FIRST_SLICE = 0.005  # seconds of the first expansion slice; queries at first are cheap and most paths are short
SLICE_SHARE = 0.25  # a slice lasts this share of the time spent so far: reading the roadmap stays a small overhead
SHORTEST_EDGE = 1e-12  # csgraph reads a zero weight as no edge: an edge between equal states weighs this


@dataclass(frozen=True)
class Roadmap:
    """The milestones of a PRM roadmap that have edges, and its edges as pairs of indices into ``states``."""

    states: np.ndarray  # (n, dof)
    components: np.ndarray  # (n,) OMPL's connected-component tag of each milestone
    edges: np.ndarray  # (m, 2), each undirected edge once


@dataclass
class Terminal:
    """The start or a goal: its configuration and the motions to milestones checked so far."""

    q: np.ndarray
    state: object  # the OMPL state at q
    checked: dict[bytes, bool] = field(default_factory=dict)  # milestone's coordinates -> the motion is valid


def neighbour_count(star: bool, milestones: int, dof: int) -> int:
    """How many nearest milestones PRM tries to connect a new one to, the new one counted in ``milestones``."""
    if not star:
        return PRM_NEIGHBORS
    return math.ceil((math.e + math.e / dof) * math.log(max(milestones, 1)))


def read_roadmap(ob, planner, info, dof: int) -> Roadmap:
    """The planner's roadmap as arrays (milestones without edges are left out by OMPL's planner data)."""
    data = ob.PlannerData(info)
    planner.getPlannerData(data)
    n = data.numVertices()
    states = np.empty((n, dof))
    components = np.empty(n, dtype=np.int64)
    pairs = []
    for i in range(n):
        vertex = data.getVertex(i)
        state = vertex.getState()
        for j in range(dof):
            states[i, j] = state[j]
        components[i] = vertex.getTag()
        pairs.extend((i, k) for k in data.getEdges(i) if i < k)
    edges = np.array(pairs, dtype=np.int64).reshape(-1, 2)
    return Roadmap(states, components, edges)


def set_state(state, q: np.ndarray):
    """``state`` (an OMPL real-vector state), set to ``q``."""
    for j in range(len(q)):
        state[j] = float(q[j])
    return state


def connect(terminal: Terminal, roadmap: Roadmap, k: int, scratch, info) -> None:
    """Checks the motions from ``terminal`` to its ``k`` nearest milestones not checked before; ``scratch``: an
    OMPL state to hold each milestone's configuration in turn (one state for all the checks, none allocated per
    check)."""
    if not len(roadmap.states):
        return
    distances = np.linalg.norm(roadmap.states - terminal.q, axis=1)
    nearest = np.argsort(distances)[:k]
    for index in nearest:
        key = roadmap.states[index].tobytes()
        if key not in terminal.checked:
            terminal.checked[key] = bool(info.checkMotion(terminal.state, set_state(scratch, roadmap.states[index])))


def connected_milestones(terminal: Terminal, indices: dict[bytes, int]) -> np.ndarray:
    """Indices of the milestones ``terminal`` has a valid motion to; ``indices``: milestone's coordinates -> index."""
    return np.array([indices[key] for key, valid in terminal.checked.items() if valid and key in indices], dtype=int)


def shortest_path(
    roadmap: Roadmap, start: Terminal, goals: list[Terminal], first_goal: bool
) -> tuple[np.ndarray, float] | None:
    """The shortest path from ``start`` through the roadmap to a goal and its length, or None where no goal is
    connected. ``first_goal``: the first goal in order that is connected (PRM's choice when any path is good
    enough), else the nearest of them."""
    indices = {q.tobytes(): i for i, q in enumerate(roadmap.states)}
    to_start = connected_milestones(start, indices)
    to_goals = [connected_milestones(goal, indices) for goal in goals]
    reachable = set(roadmap.components[to_start].tolist())
    if not any(reachable & set(roadmap.components[ends].tolist()) for ends in to_goals):
        return None
    # Nodes: the milestones, then the start, then the goals.
    n = len(roadmap.states)
    rows = [roadmap.edges[:, 0], np.full(len(to_start), n)]
    cols = [roadmap.edges[:, 1], to_start]
    for g, ends in enumerate(to_goals):
        rows.append(np.full(len(ends), n + 1 + g))
        cols.append(ends)
    rows_, cols_ = np.concatenate(rows), np.concatenate(cols)
    nodes = np.vstack([roadmap.states, start.q, *(goal.q for goal in goals)])
    weights = np.maximum(np.linalg.norm(nodes[rows_] - nodes[cols_], axis=1), SHORTEST_EDGE)
    graph = coo_matrix((weights, (rows_, cols_)), shape=(len(nodes), len(nodes))).tocsr()
    distances, previous = dijkstra(graph, directed=False, indices=n, return_predecessors=True)
    ends = [n + 1 + g for g in range(len(goals)) if np.isfinite(distances[n + 1 + g])]
    if not ends:
        return None
    end = ends[0] if first_goal else min(ends, key=lambda e: distances[e])
    route = [end]
    while route[-1] != n:
        route.append(int(previous[route[-1]]))
    return nodes[route[::-1]], float(distances[end])


def direct_path(start: Terminal, goals: list[Terminal], info, first_goal: bool) -> tuple[np.ndarray, float] | None:
    """The straight motion from the start to a goal where one is valid, and its length: PRM tries it first (the
    start is a new goal's only neighbour in a new roadmap), and no path through the roadmap to that goal is shorter.
    ``first_goal`` as for :func:`shortest_path`."""
    valid = [goal for goal in goals if info.checkMotion(start.state, goal.state)]
    if not valid:
        return None
    lengths = [float(np.linalg.norm(goal.q - start.q)) for goal in valid]
    pick = 0 if first_goal else int(np.argmin(lengths))
    return np.array([start.q, valid[pick].q]), lengths[pick]


def roadmap_path(
    ob,
    planner,
    space,
    info,
    start: np.ndarray,
    goals: list[np.ndarray],
    timeout: float,
    star: bool,
    improve: bool,
) -> np.ndarray | None:
    """Waypoints of a path from ``start`` to one of ``goals`` on ``planner``'s roadmap (an ``og.PRM`` or
    ``og.PRMstar`` that has been set up), grown in this thread for at most ``timeout`` seconds; None if none was
    found. The first path found is returned unless ``improve``: then the roadmap grows for the whole ``timeout``
    and the shortest path found is returned. ``goals`` in order of preference; invalid ones are skipped, as PRM
    skips them."""
    began = time.perf_counter()
    deadline = began + timeout
    dof = len(start)
    origin = Terminal(np.asarray(start, dtype=float), set_state(space.allocState(), start))
    ends = [Terminal(np.asarray(q, dtype=float), set_state(space.allocState(), q)) for q in goals]
    scratch = space.allocState()
    ends = [goal for goal in ends if info.isValid(goal.state)]
    if not ends or not info.isValid(origin.state):
        return None
    best = direct_path(origin, ends, info, first_goal=not improve)
    nearest = min(float(np.linalg.norm(goal.q - origin.q)) for goal in ends)
    if best is not None and (not improve or best[1] <= nearest):
        return best[0]  # nothing is shorter than a straight motion to the nearest goal
    grow = True
    while (now := time.perf_counter()) < deadline:
        slice_ = min(BUILD_TIME, max(FIRST_SLICE, SLICE_SHARE * (now - began)))
        if grow:
            planner.growRoadmapPtc(ob.timedPlannerTerminationCondition(min(2 * slice_, deadline - now)))
        else:
            planner.expandRoadmapPtc(ob.timedPlannerTerminationCondition(min(slice_, deadline - now)))
        grow = not grow
        roadmap = read_roadmap(ob, planner, info, dof)
        # A terminal counts as the newest milestone, as it would in PRM's own roadmap.
        k = neighbour_count(star, planner.milestoneCount() + 1, dof)
        for terminal in (origin, *ends):
            connect(terminal, roadmap, k, scratch, info)
        found = shortest_path(roadmap, origin, ends, first_goal=not improve)
        if found is not None and (best is None or found[1] < best[1]):
            best = found
        if best is not None and not improve:
            break
    return None if best is None else best[0]
