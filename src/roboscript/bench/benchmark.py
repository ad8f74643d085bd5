"""The benchmark: tasks x trials for one policy and robot, resumable, with a summary in the paper's layout."""

from __future__ import annotations

import re
import sys
import time
from pathlib import Path

from roboscript.bench.metrics import task_result
from roboscript.bench.progress import ProgressBar
from roboscript.bench.results import RunDirectory, keep_video, provenance, with_videos
from roboscript.bench.runner import TrialPool
from roboscript.bench.stored_programs import PREFIX as PROGRAMS_PREFIX
from roboscript.bench.stored_programs import StoredProgram, load_program_store
from roboscript.bench.tasks import DEFAULT_SUITE, get_task, load_suite
from roboscript.bench.trial import LLMAuthor, TrialRecord, TrialSpec
from roboscript.errors import InvalidArgumentError
from roboscript.perception.modes import GROUND_TRUTH, PerceptionMode

POLICIES = ("reference", "llm:SPEC", "programs:PATH")


def policy_llm(policy: str) -> str | None:
    """The LLM spec of an ``llm:SPEC`` policy, None for stored programs (the reference ones or others)."""
    if policy == "reference" or (policy.startswith(PROGRAMS_PREFIX) and len(policy) > len(PROGRAMS_PREFIX)):
        return None
    if policy.startswith("llm:") and len(policy) > 4:
        return policy[4:]
    raise InvalidArgumentError(
        f"unknown policy {policy!r}; policies: {', '.join(POLICIES)} (e.g. llm:openai:gpt-4o, programs:generated/)"
    )


def policy_programs(policy: str, tasks: list[str], suite: str = DEFAULT_SUITE) -> dict[str, StoredProgram]:
    """The program each task runs under ``policy``, with where it came from (for an LLM policy: what writes it)."""
    llm = policy_llm(policy)
    catalogue = load_suite(suite)
    if llm is not None:
        return {t: StoredProgram(t, f"generated in each trial by {llm}", f"llm:{llm}") for t in tasks}
    if policy == "reference":
        return {t: StoredProgram(t, catalogue[t].reference_program(), str(catalogue[t].reference)) for t in tasks}
    path = policy[len(PROGRAMS_PREFIX) :]
    store = load_program_store(path, catalogue)
    for note in store.unmatched:
        print(f"stored programs: not used: {note}", file=sys.stderr)
    return store.require(tasks, path)


def run_label(policy: str, repair_rounds: int = 0) -> str:
    """The policy as runs are told apart by: with repair, ``<policy>+repair<K>``."""
    return f"{policy}+repair{repair_rounds}" if repair_rounds else policy


def folder_label(policy: str, repair_rounds: int = 0) -> str:
    """The policy as a folder's name calls it, short and safe: an LLM policy by its model (``llm-gpt-4o``, not the
    endpoint's URL), stored programs by their folder or file (``programs-gpt4_answers``), with ``+repair<K>``."""
    from roboscript.llm.spec import short_name

    llm = policy_llm(policy)
    if llm is not None:
        name = f"llm-{short_name(llm)}"
    elif policy.startswith(PROGRAMS_PREFIX):
        name = f"programs-{Path(policy[len(PROGRAMS_PREFIX) :].rstrip('/')).stem}"
    else:
        name = policy
    return re.sub(r"[^A-Za-z0-9._+-]+", "_", run_label(name, repair_rounds))


def default_out(
    policy: str,  # the folder's label (folder_label)
    robot: str,
    perception: PerceptionMode | str = GROUND_TRUTH,
    suite: str = DEFAULT_SUITE,
    backend: str = "mujoco",
) -> str:
    """``out/bench/<policy>_<robot>``, with the suite, the perception mode and the backend where they are not the
    defaults (``<policy>_<suite>_<perception>_<robot>_ros``); the policy as :func:`folder_label` names it."""
    mode = "" if str(perception) == "gt" else f"_{perception}"
    robot = robot if backend == "mujoco" else f"{robot}_{backend}"
    label = "" if suite == DEFAULT_SUITE else "_" + Path(suite).stem
    return f"out/bench/{policy}{label}{mode}_{robot}"


def trial_specs(
    task: str,
    program: str | StoredProgram | LLMAuthor,
    robot: str,
    trials: int,
    seed: int,
    timeout: float,
    video: str | None = None,
    instruction: str | None = None,
    world: str | None = None,
    perception: PerceptionMode | str = GROUND_TRUTH,
    suite: str = DEFAULT_SUITE,
    backend: str = "mujoco",
    robot_config: str | None = None,
    record: str | None = None,
) -> list[TrialSpec]:
    """Trial ``i`` uses seed ``seed + i``; with several trials, videos and recordings get a ``_trial<i>``
    suffix."""
    if trials < 1:
        raise InvalidArgumentError(f"trials must be at least 1, got {trials}")
    specs = []
    for i in range(trials):
        path, recording = _numbered(video, i, trials), _numbered(record, i, trials)
        specs.append(
            TrialSpec(
                task,
                robot,
                i,
                seed + i,
                program,
                timeout,
                path,
                instruction=instruction,
                world=world,
                perception=perception,
                suite=suite,
                backend=backend,
                robot_config=robot_config,
                record=recording,
            )
        )
    return specs


def _numbered(path: str | None, trial: int, trials: int) -> str | None:
    """``path`` itself for one trial; ``<stem>_trial<i><suffix>`` for each of several."""
    if path is None or trials == 1:
        return path
    return str(Path(path).with_name(f"{Path(path).stem}_trial{trial}{Path(path).suffix}"))


def open_run(
    out: str | Path,
    policy: str,
    tasks: list[str],
    robot: str,
    trials: int,
    seed: int,
    timeout: float = 300.0,
    repair_rounds: int = 0,
    perception: PerceptionMode | str = GROUND_TRUTH,
    suite: str = DEFAULT_SUITE,
    backend: str = "mujoco",
    robot_config: str | None = None,
    programs: dict[str, StoredProgram] | None = None,
) -> tuple[RunDirectory, list[TrialSpec]]:
    """Opens (or reopens, refusing other settings or programs) the run directory ``out`` and lists the trials it
    still needs; ``programs`` are the policy's (looked up here where not given)."""
    programs = programs if programs is not None else policy_programs(policy, tasks, suite)
    llm = policy_llm(policy)
    # Every trial is made (and its settings checked) before the run directory: a refused run leaves nothing behind.
    every = [
        s
        for t in tasks
        for s in trial_specs(
            t,
            programs[t] if llm is None else LLMAuthor(llm, repair_rounds),
            robot,
            trials,
            seed,
            timeout,
            perception=perception,
            suite=suite,
            backend=backend,
            robot_config=robot_config,
        )
    ]
    texts = {t: p.program for t, p in programs.items()}
    run = RunDirectory(
        out,
        provenance(
            run_label(policy, repair_rounds), robot, trials, seed, texts, str(perception), repair_rounds, suite, backend
        ),
    )
    done = run.done()
    return run, [s for s in every if (s.task, s.robot, s.trial) not in done]


def run_benchmark(
    policy: str,
    tasks: list[str] | None,
    robot: str,
    trials: int,
    seed: int,
    out: str | Path,
    jobs: int,
    timeout: float = 300.0,
    progress: bool = True,
    repair_rounds: int = 0,
    perception: PerceptionMode | str = GROUND_TRUTH,
    suite: str = DEFAULT_SUITE,
    backend: str = "mujoco",
    robot_config: str | None = None,
    videos: str = "none",
) -> dict:
    """Runs (or resumes) the benchmark of ``suite`` in ``out``; returns ``{"tasks": {id: exec object},
    "wall_time_s", "out", "summary", "ran"}`` (``ran``: how many trials this call ran; the rest were recorded
    before). ``videos`` (none, failed, all): which trials keep a video in ``<out>/videos``. ``progress`` shows a
    bar with the time left on stderr."""
    tasks = list(tasks or load_suite(suite))
    for t in tasks:
        get_task(t, suite)
    started = time.perf_counter()
    with TrialPool(jobs) as pool:  # made first: a bad number of jobs is refused before the run directory is made
        run, specs = open_run(
            out, policy, tasks, robot, trials, seed, timeout, repair_rounds, perception, suite, backend, robot_config
        )
        specs = with_videos(specs, run.path, videos)
        total = len(tasks) * trials
        bar = ProgressBar(total, total - len(specs)) if progress else None

        def on_result(spec: TrialSpec, record: TrialRecord) -> None:
            keep_video(spec, record, videos)
            run.append(record)
            run.write_summary(tasks)
            if bar is not None:
                bar.update(record)

        pool.run(specs, on_result=on_result)
    summary = run.write_summary(tasks)
    records = run.records()
    return {
        "tasks": {
            t: task_result(t, robot, [r for r in records if r.task == t and r.robot == robot and r.trial < trials])
            for t in tasks
        },
        "wall_time_s": round(time.perf_counter() - started, 2),
        "out": str(run.path),
        "summary": summary["tasks"],
        "ran": len(specs),
    }
