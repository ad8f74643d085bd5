"""Stored programs as a policy (``--policy programs:PATH``): programs written earlier, by any LLM or by hand.

``PATH`` is a folder or a file. A folder holds ``<task_id>.py`` files and/or files in the original RoboScript's
generated-code format; a ``.json`` file is in that format: a list of entries with

- ``query``: the task query the program was written for (``# objects = [...] ; # instruction.``),
- ``code_str``: the program,
- ``src_fs``: a mapping from a function's name to the source generated for it (optional).

The program is the functions of ``src_fs`` followed by ``code_str``. An entry is matched to its task by its query:
the same names, quoted or not, and the same instruction, compared without trailing periods and spaces and without
case (the original's stored queries begin with ``# `` and end with ``.`` or ``..``). Entries and files that match
no task are reported, not run.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from roboscript.bench.task_file import Task, query_key
from roboscript.errors import UsageError

PREFIX = "programs:"


class StoredProgramsError(UsageError, ValueError):
    """Stored programs that cannot be used; the message names the file, the entry and the problem."""


@dataclass(frozen=True)
class StoredProgram:
    """A program for one task, and where it came from (``file.json[2]``, ``folder/simple_0.py``)."""

    task: str
    program: str
    source: str


@dataclass(frozen=True)
class ProgramStore:
    """What a programs path holds for a suite: a program per matched task, and what matched nothing."""

    programs: dict[str, StoredProgram]
    unmatched: list[str]

    def require(self, tasks: list[str], path: str) -> dict[str, StoredProgram]:
        """The programs of ``tasks``; a clear error naming the tasks that have none."""
        missing = [t for t in tasks if t not in self.programs]
        if missing:
            found = ", ".join(sorted(self.programs)) or "none"
            raise StoredProgramsError(
                f"no stored program in {path} for {', '.join(missing)} (programs found for: {found}); "
                "run only those with --tasks, or add <task_id>.py files or entries whose query matches the task's"
            )
        return {t: self.programs[t] for t in tasks}


def compose(code_str: str, functions: dict[str, str]) -> str:
    """A program in the original's form: its generated functions, then its main code."""
    parts = [source.rstrip() for source in functions.values()] + [code_str.rstrip()]
    return "\n\n\n".join(p for p in parts if p) + "\n"


def _entries(path: Path) -> list[tuple[str, str, str]]:
    """``(source, query, program)`` of every entry of a generated-code file."""
    try:
        data = json.loads(path.read_text())
    except (OSError, json.JSONDecodeError) as exc:
        raise StoredProgramsError(f"programs file {path}: is not readable JSON: {exc}") from exc
    if not isinstance(data, list):
        raise StoredProgramsError(
            f"programs file {path}: expected a list of entries with 'query', 'code_str' and 'src_fs', "
            f"got {type(data).__name__}"
        )
    out = []
    for i, entry in enumerate(data):
        where = f"programs file {path}: [{i}]"
        if not isinstance(entry, dict):
            raise StoredProgramsError(f"{where}: expected an object with 'query' and 'code_str', got {entry!r}")
        query, code = entry.get("query"), entry.get("code_str")
        functions = entry.get("src_fs") or {}
        if not isinstance(query, str) or not query.strip():
            raise StoredProgramsError(
                f"{where}: 'query' must be the task query the program was written for, got {query!r}"
            )
        if not isinstance(code, str):
            raise StoredProgramsError(f"{where}: 'code_str' must be the program's source, got {code!r}")
        if not isinstance(functions, dict) or not all(
            isinstance(k, str) and isinstance(v, str) for k, v in functions.items()
        ):
            shown = repr(functions)[:120]
            raise StoredProgramsError(f"{where}: 'src_fs' must map function names to their source code, got {shown}")
        out.append((f"{path}[{i}]", query, compose(code, functions)))
    return out


def load_program_store(path: str | Path, tasks: dict[str, Task]) -> ProgramStore:
    """The programs that ``path`` (a folder, or a generated-code ``.json`` file) holds for ``tasks``. In a
    folder, a ``.json`` file that is not in the generated-code format is reported and passed over."""
    path = Path(path)
    if path.is_dir():
        files = sorted(p for p in path.iterdir() if p.suffix in (".py", ".json"))
    elif path.is_file() and path.suffix == ".json":
        files = [path]
    else:
        raise StoredProgramsError(
            f"{path} is neither a folder of <task_id>.py or .json files nor a .json file of generated code"
        )
    by_query: dict[tuple[tuple[str, ...], str], str] = {}
    for task in tasks.values():
        key = query_key(task.query)
        if key in by_query:
            raise StoredProgramsError(
                f"tasks {by_query[key]} and {task.id} ask the same query, so a stored program cannot tell them apart"
            )
        by_query[key] = task.id
    found: dict[str, StoredProgram] = {}
    unmatched: list[str] = []

    def add(task: str, program: str, source: str) -> None:
        if task in found:
            raise StoredProgramsError(f"two stored programs for {task}: {found[task].source} and {source}")
        found[task] = StoredProgram(task, program, source)

    for file in files:
        if file.suffix == ".py":
            if file.stem in tasks:
                add(file.stem, file.read_text(), str(file))
            else:
                unmatched.append(f"{file} (no task {file.stem!r})")
            continue
        try:
            entries = _entries(file)
        except StoredProgramsError as exc:
            if len(files) == 1 and file == path:
                raise
            unmatched.append(f"{file} (not in the generated-code format: {exc})")
            continue
        for source, query, program in entries:
            task = by_query.get(query_key(query))
            if task is None:
                unmatched.append(f"{source} (its query matches no task: {query.strip()[:80]!r})")
            else:
                add(task, program, source)
    return ProgramStore(found, unmatched)
