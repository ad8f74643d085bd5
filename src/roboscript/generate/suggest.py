"""Tasks an LLM suggests for a scene: instructions with checks in the task file's form, each validated against
the world before it is kept.

The model is given the scene's description and the names programs use, and asked for a YAML list of
``{instruction, checks}``. Each suggestion is kept only if it passes the task file's own validation (the names
exist, the checks are well formed) and is not already done at the start (its checks, evaluated on the settled
world, do not all pass). Everything else is rejected with its reason; a reply that is not such a list keeps
nothing.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from roboscript.bench.task_file import Task, TaskFileError, parse_suite
from roboscript.codegen.prompt import task_query
from roboscript.datafile import load_yaml
from roboscript.llm.base import LLM, LLMRequest
from roboscript.sim.ground_truth import GroundTruth
from roboscript.sim.world_file import WorldSpec

SYSTEM = """You suggest manipulation tasks for a robot arm with a two-finger gripper at a table.
Each task is an instruction a person could give, and the checks that decide, from the scene at the end, whether it was
done. Reply with a YAML list in a ```yaml block and nothing else; each item has `instruction` and `checks`.
A check is one of:
  - in: [OBJECT, CONTAINER_OR_DRAWER]       # at least 80% of the object's box inside (bowls, baskets, drawers)
  - on: [OBJECT, OBJECT_OR_table]           # resting over it (plates, saucers, other objects, the table)
  - near: [OBJECT, OBJECT]                  # beside it, at most 8 cm apart and not on it
  - {at: OBJECT, start_of: OTHER_OBJECT}    # within 10 cm of where the other object was at the start
  - {joint: DRAWER, above: METRES}          # a drawer pulled open further than METRES
Use only the names listed, exactly as written. Every task must change something: its checks must not already hold."""

EXAMPLE = """```yaml
- instruction: put the apple into the white bowl
  checks:
    - in: [apple, white_bowl]
- instruction: open the top drawer and put the toy car into it
  checks:
    - {joint: cabinet.drawer_0, above: 0.1}
    - in: [toy_car, cabinet.drawer_0]
```"""

_BLOCK = re.compile(r"```(?:ya?ml)?\s*\n(.*?)```", re.DOTALL)
_ITEM_FIELDS = {"instruction", "checks"}


@dataclass(frozen=True)
class Rejection:
    """A suggestion that was not kept, and why."""

    index: int  # its place in the reply's list; -1 for the whole reply
    suggestion: Any
    reason: str


@dataclass
class Suggestions:
    """What one reply gave: the tasks kept (task file entries, world as given) and the rejections."""

    world: str
    kept: list[dict] = field(default_factory=list)
    rejected: list[Rejection] = field(default_factory=list)


def suggestion_request(world: WorldSpec, description: str, count: int, temperature: float = 0.7) -> LLMRequest:
    """The request for ``count`` tasks in ``world`` described by ``description``."""
    user = (
        f"Scene: {description}\n\nNames: {', '.join(world.query_names())}\n\n"
        f"Suggest {count} different tasks for this scene, from simple (one object) to harder (several objects, "
        f"a drawer, an order of steps). For example:\n{EXAMPLE}"
    )
    messages = ({"role": "system", "content": SYSTEM}, {"role": "user", "content": user})
    return LLMRequest(messages, temperature=temperature, max_tokens=2048)


def parse_reply(text: str) -> list:
    """The list a reply holds (in a ```yaml block, or the whole text); ``ValueError`` saying what is wrong."""
    block = _BLOCK.search(text)
    source = block.group(1) if block else text
    try:
        data = load_yaml(source)  # YAML 1.2: the key `on:` stays a key, not True
    except yaml.YAMLError as exc:
        raise ValueError(f"the reply is not YAML: {str(exc).splitlines()[0]}") from None
    if not isinstance(data, list) or not data:
        raise ValueError(f"the reply must be a YAML list of {{instruction, checks}}, got {type(data).__name__}")
    return data


def validate_suggestion(
    item: Any, index: int, world: WorldSpec, world_ref: str, base: Path, gt: GroundTruth
) -> tuple[dict | None, str]:
    """``(task entry, "")`` for a suggestion that holds, else ``(None, reason)``."""
    if not isinstance(item, dict):
        return None, f"a suggestion is a mapping with instruction and checks, got {item!r}"
    unknown = sorted(str(k) for k in set(item) - _ITEM_FIELDS)
    if unknown:
        return None, f"unknown field {unknown[0]!r}; a suggestion has only: instruction, checks"
    instruction = item.get("instruction")
    if not isinstance(instruction, str) or not instruction.strip():
        return None, f"field 'instruction' must be non-empty text, got {instruction!r}"
    instruction = " ".join(instruction.split())
    entry = {
        "id": f"suggested_{index}",
        "world": world_ref,
        "query": task_query(world.query_names(), instruction),
        "checks": item.get("checks"),
    }
    try:
        (task,) = parse_suite({"suite": "suggested", "tasks": [entry]}, "<suggestion>", base)
    except TaskFileError as exc:
        where = exc.entry.partition("'.")[2]  # checks[1], of the entry "tasks[0] 'suggested_0'.checks[1]"
        return None, f"{where}: {exc.problem}" if where else exc.problem
    done = _already_done(task, gt)
    if done:
        return None, f"already done at the start: {done}"
    return entry, ""


def _already_done(task: Task, gt: GroundTruth) -> str:
    """The checks, in words, if every one of them holds in the world as it starts; else ''."""
    results = [c.evaluate(gt) for c in task.build_checks(gt)]
    return ", ".join(r.name for r in results) if all(r.passed for r in results) else ""


def suggest_tasks(
    llm: LLM, world: WorldSpec, world_ref: str, base: Path, description: str, gt: GroundTruth, count: int = 5
) -> Suggestions:
    """Asks ``llm`` for ``count`` tasks in ``world`` and keeps those that validate; ``world_ref`` is how the kept
    entries name the world (relative to ``base``, the suite file's folder)."""
    result = Suggestions(world_ref)
    reply = llm.complete(suggestion_request(world, description, count)).text
    try:
        items = parse_reply(reply)
    except ValueError as exc:
        result.rejected.append(Rejection(-1, reply, str(exc)))
        return result
    seen: set[str] = set()
    for index, item in enumerate(items):
        entry, reason = validate_suggestion(item, index, world, world_ref, base, gt)
        if entry is not None and entry["query"] in seen:
            entry, reason = None, "the same instruction was suggested before"
        if entry is None:
            result.rejected.append(Rejection(index, item, reason))
            continue
        seen.add(entry["query"])
        result.kept.append(entry)
    return result
