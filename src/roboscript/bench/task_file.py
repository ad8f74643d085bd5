"""Task files: a suite of benchmark tasks as data (YAML or JSON), parsed and validated into :class:`Task` objects.

A suite file names the suite and lists its tasks; each task names its world, gives the query an LLM is asked
(``objects = [...] ; # instruction``, character for character) and the checks that decide whether it was done::

    suite: paper
    description: The eight tasks of the RoboScript paper.
    tasks:
      - id: simple_0
        label: simple_0                        # the task's label in the original repository (optional)
        world: world_2_pick_and_place          # a packaged world, or a world file relative to this file
        query: "objects = [table, cabinet, apple, footed_bowl] ; # place the apple into the footed bowl"
        checks:
          - in: [apple, footed_bowl]           # 80% of the apple's box inside the bowl's
          - on: [apple, table]                 # over it, resting no lower than its bottom
          - near: [apple, banana]              # beside it: at most 8 cm apart, not on it
          - {at: apple, start_of: banana}      # within 10 cm of where the banana was at the start
          - {at: apple, position: [0.1, 0.2, 0.86]}
          - {at: banana, start_of: banana, within: 0.05}   # stayed within 5 cm of where it was
          - {joint: cabinet.drawer_1, above: 0.15}   # opened beyond 15 cm (radians for doors)
          - {on: [apple, white_ceramic_plate], not: true}   # the check must fail

Every problem is a :class:`TaskFileError` naming the file, the entry (``tasks[2] 'moderate_0'.checks[1]``) and what
is wrong, with the valid choices: unknown fields, a query that is not in the query form or lists a name its world
lacks, a check on an object that is not there or in something that holds nothing.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from roboscript.bench.checks import Check
from roboscript.codegen.prompt import task_query
from roboscript.datafile import DataFileError, Reader, entry_label, names_a_file, read_data_file
from roboscript.errors import InvalidArgumentError, did_you_mean
from roboscript.names import kind_of
from roboscript.sim.ground_truth import GroundTruth
from roboscript.sim.world_catalog import load_world
from roboscript.sim.world_file import TABLE_NAME, WorldFileError, WorldSpec

CHECK_KINDS = ("in", "on", "near", "at", "joint")
_QUERY = re.compile(r"^\s*#?\s*objects\s*=\s*\[(?P<names>[^\]]*)\]\s*;\s*#\s?(?P<instruction>.*)$", re.DOTALL)
_ID = re.compile(r"^[A-Za-z0-9_.-]+$")
_SUITE_FIELDS = {"suite", "version", "description", "source", "tasks"}
_TASK_FIELDS = {"id", "label", "world", "query", "checks", "reference"}


class TaskFileError(DataFileError):
    """A task file that cannot be loaded; the message names the file, the entry and the problem."""

    kind = "task"


@dataclass(frozen=True)
class CheckSpec:
    """One check as the task file states it; :meth:`resolve` makes it concrete for a trial (``start_of`` is read
    from the world as it starts)."""

    kind: str  # in, on, at, joint
    subject: str
    target: str = ""  # the receptacle of in/on
    start_of: str = ""  # at: where this object was at the start
    position: tuple[float, float, float] | None = None  # at: a fixed point
    above: float = 0.0  # joint: opened beyond this (metres or radians)
    negate: bool = False
    within: float = 0.0  # at: how near, in metres (the checks' default where 0)

    def resolve(self, gt: GroundTruth) -> Check:
        point = self.position
        if self.kind == "at" and self.start_of:
            point = tuple(float(v) for v in gt.box(self.start_of).center)
        threshold = self.within if self.kind == "at" else self.above
        return Check(self.kind, self.subject, self.target, point, threshold, self.negate)

    def describe(self) -> str:
        """The check in words of the file's form, e.g. ``in(apple, footed_bowl)``, ``at(apple, start of banana)``."""
        if self.kind in ("in", "on", "near"):
            text = f"{self.kind}({self.subject}, {self.target})"
        elif self.kind == "at":
            where = f"start of {self.start_of}" if self.start_of else str(list(self.position or ()))
            text = f"at({self.subject}, {where})" + (f" within {self.within:g} m" if self.within else "")
        else:
            text = f"joint({self.subject}) > {self.above:g}"
        return f"not {text}" if self.negate else text


@dataclass(frozen=True)
class Task:
    """A benchmark task: its world, the query an LLM is given, and the checks of its result.

    ``reference``: the file of its verified program (``<suite>/<id>.py`` beside the suite file, or the file the
    task's ``reference`` field names from there), if there is one.
    """

    id: str
    suite: str
    world: str
    query: str
    checks: tuple[CheckSpec, ...]
    label: str = ""
    reference: Path | None = None

    @property
    def instruction(self) -> str:
        """What the query asks, without its object list."""
        return parse_query(self.query)[1]

    @property
    def object_names(self) -> list[str]:
        """The names the query lists."""
        return parse_query(self.query)[0]

    def query_for(self, instruction: str | None = None) -> str:
        """The query given to an LLM: the task's own, or its object list with another ``instruction``."""
        if not instruction:
            return self.query
        return task_query(self.object_names, instruction)

    def build_checks(self, gt: GroundTruth) -> list[Check]:
        """The checks of one trial, with positions from the world as it starts."""
        return [c.resolve(gt) for c in self.checks]

    def reference_program(self) -> str:
        """The task's verified program, written against the tool API only."""
        if self.reference is None or not self.reference.is_file():
            where = f" (looked for {self.reference})" if self.reference else ""
            raise KeyError(f"task {self.id!r} of suite {self.suite!r} has no reference program{where}")
        return self.reference.read_text()


def parse_query(query: str) -> tuple[list[str], str]:
    """``(names, instruction)`` of a query ``objects = [a, b, ...] ; # instruction`` (names quoted or not; the
    eval-items form with a leading ``# `` too). Raises ``ValueError`` naming the expected form."""
    match = _QUERY.match(query) if isinstance(query, str) else None
    if match is None:
        raise InvalidArgumentError(f"a query reads 'objects = [table, apple, ...] ; # instruction', got {query!r}")
    names = [n.strip().strip("'\"") for n in match["names"].split(",")]
    return [n for n in names if n], match["instruction"]


def query_key(query: str) -> tuple[tuple[str, ...], str] | None:
    """What two queries are compared by (a stored program's and a task's): the names, quoted or not, and the
    instruction without trailing periods and spaces, in lower case with single spaces (the original's eval items
    end its queries with ``.``, its stored programs with ``..``); None for text that is no query."""
    try:
        names, instruction = parse_query(query)
    except ValueError:
        return None
    return tuple(names), " ".join(instruction.split()).lower().rstrip(". ")


# ---------------------------------------------------------------------------------------------------------------
# Parsing


def _entry(source: str, entry: str, data: Any, allowed: set[str]) -> Reader:
    return Reader(source, entry, data, allowed, TaskFileError)


def _name_check(entry: Reader, name: object, valid: list[str], kinds: str) -> str:
    """``name`` if it is one of ``valid`` (the world's ``kinds``), else the entry fails naming the valid ones."""
    if not isinstance(name, str) or name not in valid:
        close = did_you_mean(name, valid)
        hint = f"{close} " if close else ""
        entry.fail(f"{name!r} is not one of the world's {kinds}; {hint}valid: {', '.join(valid) or 'none'}")
    return name


def _pair(entry: Reader, kind: str) -> tuple[str, str]:
    value = entry.data[kind]
    if not (isinstance(value, list) and len(value) == 2):
        entry.fail(f"'{kind}' takes [object, receptacle], e.g. {kind}: [apple, footed_bowl]; got {value!r}")
    return value[0], value[1]


def _receptacles(world: WorldSpec, kind: str) -> list[str]:
    """What ``in`` may name (containers, drawers, and doors for the compartments behind them), ``on`` (any
    object, and the table) and ``near`` (any object or piece of furniture)."""
    if kind == "in":
        containers = [o.name for o in world.objects if o.type.container]
        return containers + [p for p in world.part_names() if kind_of(p) in ("drawer", "door")]
    if kind == "near":
        return [*world.object_names(), *(c.name for c in world.cabinets)]
    return [TABLE_NAME, *world.object_names()]


def _parse_check(source: str, entry_name: str, data: Any, world: WorldSpec) -> CheckSpec:
    if not isinstance(data, dict):
        raise TaskFileError(source, entry_name, f"a check is a mapping such as {{in: [apple, bowl]}}, got {data!r}")
    kinds = [k for k in CHECK_KINDS if k in data]
    if len(kinds) != 1:
        raise TaskFileError(
            source, entry_name, f"a check names exactly one of {', '.join(CHECK_KINDS)}; got {sorted(map(str, data))}"
        )
    kind = kinds[0]
    at_fields = {"start_of", "position", "within"}
    extra = {"in": set(), "on": set(), "near": set(), "at": at_fields, "joint": {"above"}}[kind]
    entry = _entry(source, entry_name, data, {kind, "not", *extra})
    negate = data.get("not", False)
    if not isinstance(negate, bool):
        entry.fail(f"field 'not' must be true or false, got {negate!r}")
    parse = {"in": _relation_check, "on": _relation_check, "near": _relation_check, "at": _at_check}.get(
        kind, _joint_check
    )
    return parse(entry, kind, world, negate)


def _relation_check(entry: Reader, kind: str, world: WorldSpec, negate: bool) -> CheckSpec:
    """``in: [object, container or drawer]``, ``on: [object, object or the table]`` or ``near: [object, object]``."""
    subject, target = _pair(entry, kind)
    _name_check(entry, subject, world.object_names(), "objects")
    what = {"in": "containers, drawers and doors", "on": "objects and the table", "near": "objects and furniture"}
    _name_check(entry, target, _receptacles(world, kind), what[kind])
    if subject == target:
        entry.fail(f"an object cannot be {kind} itself: {subject!r}")
    return CheckSpec(kind, subject, target, negate=negate)


def _at_check(entry: Reader, kind: str, world: WorldSpec, negate: bool) -> CheckSpec:
    """``{at: object, start_of: other}`` or ``{at: object, position: [x, y, z]}``, optionally ``within: metres``."""
    objects = world.object_names()
    subject = _name_check(entry, entry.data["at"], objects, "objects")
    if ("start_of" in entry.data) == ("position" in entry.data):
        entry.fail("'at' takes either start_of: OBJECT (where it was at the start) or position: [x, y, z]")
    within = 0.0
    if "within" in entry.data:
        within = entry.number("within")
        if not within > 0:
            entry.fail(f"'within' is how near in metres, a number above 0, e.g. within: 0.05; got {within!r}")
    if "start_of" in entry.data:
        start = _name_check(entry, entry.data["start_of"], objects, "objects")
        return CheckSpec(kind, subject, start_of=start, negate=negate, within=within)
    return CheckSpec(kind, subject, position=entry.vector("position", (3,)), negate=negate, within=within)


def _joint_check(entry: Reader, kind: str, world: WorldSpec, negate: bool) -> CheckSpec:
    """``{joint: drawer or door, above: value}``: opened beyond ``value`` metres (radians for a door)."""
    articulated = [p for p in world.part_names() if kind_of(p) in ("drawer", "door")]
    subject = _name_check(entry, entry.data["joint"], articulated, "drawers and doors")
    if "above" not in entry.data:
        entry.fail("'joint' takes above: VALUE, how far it must be open (metres for a drawer, radians for a door)")
    return CheckSpec(kind, subject, above=entry.number("above"), negate=negate)


def _load_task_world(entry: Reader, world: str, base: Path) -> tuple[str, WorldSpec]:
    """The world a task names: a packaged world, or a world file relative to the task file."""
    reference = str((base / world).resolve()) if names_a_file(world) else world
    try:
        return reference, load_world(reference)
    except (WorldFileError, KeyError) as exc:
        message = exc.args[0] if isinstance(exc, KeyError) and exc.args else str(exc)
        entry.fail(f"world {world!r}: {message}")


def _parse_task(source: str, index: int, data: Any, suite: str, base: Path, programs: Path | None) -> Task:
    label = entry_label("tasks", index, data, key="id")
    entry = _entry(source, label, data, _TASK_FIELDS)
    task_id = entry.string("id")
    if not _ID.match(task_id):
        entry.fail(f"id {task_id!r} may hold letters, digits, '_', '.' and '-' only")
    world_ref, world = _load_task_world(entry, entry.string("world"), base)
    query = entry.string("query")
    try:
        names, instruction = parse_query(query)
    except ValueError as exc:
        entry.fail(f"query: {exc}")
    if not instruction.strip():
        entry.fail("query: the instruction after '; #' is empty")
    valid = world.query_names()
    missing = [n for n in names if n not in valid]
    if missing:
        listed = ", ".join(map(repr, missing))
        entry.fail(f"query lists {listed}, not in world {world.name!r}; its names: {', '.join(valid)}")
    checks = data.get("checks")
    if not isinstance(checks, list) or not checks:
        entry.fail("field 'checks' must be a non-empty list, e.g. [{in: [apple, footed_bowl]}]")
    specs = tuple(_parse_check(source, f"{label}.checks[{k}]", c, world) for k, c in enumerate(checks))
    label_in_source = entry.text("label")
    reference = programs / f"{task_id}.py" if programs is not None else None
    if "reference" in data:  # another task's program, where it does the same (a suite's variant of a task)
        if programs is None:
            entry.fail("field 'reference' needs the suite to be a file, whose folder it is found from")
        reference = (base / entry.string("reference")).resolve()
        if not reference.is_file():
            entry.fail(f"reference: no program at {reference} (give a path from the suite file's folder)")
    return Task(task_id, suite, world_ref, query, specs, label_in_source, reference)


def parse_suite(data: Any, source: str = "<memory>", base: Path | None = None) -> list[Task]:
    """Validates a suite given as parsed YAML/JSON data; ``base`` is where relative world files and the reference
    programs' folder are found (the file's own folder; without one, the tasks have no reference programs).
    Raises :class:`TaskFileError`."""
    entry = _entry(source, "suite", data, _SUITE_FIELDS)
    suite = entry.string("suite")
    for optional in ("description", "source"):
        entry.text(optional)  # optional, but text where it is given
    version = data.get("version", 1)
    if isinstance(version, bool) or not isinstance(version, int) or version < 1:
        entry.fail(f"field 'version' must be a whole number from 1, got {version!r}")
    if not _ID.match(suite):
        entry.fail(f"suite {suite!r} may hold letters, digits, '_', '.' and '-' only")
    items = data.get("tasks")
    if not isinstance(items, list) or not items:
        entry.fail("field 'tasks' must be a non-empty list of tasks")
    programs = base / suite if base is not None else None
    tasks = [_parse_task(source, i, item, suite, base or Path.cwd(), programs) for i, item in enumerate(items)]
    ids = [t.id for t in tasks]
    repeated = sorted({i for i in ids if ids.count(i) > 1})
    if repeated:
        entry.fail(f"task ids must be unique; repeated: {', '.join(repeated)}")
    return tasks


def load_suite_file(path: str | Path) -> list[Task]:
    """Reads and validates a ``.yaml``/``.yml``/``.json`` suite file."""
    path = Path(path)
    return parse_suite(read_data_file(path, TaskFileError), str(path), path.parent.resolve())


__all__ = [
    "CHECK_KINDS",
    "CheckSpec",
    "Task",
    "TaskFileError",
    "load_suite_file",
    "parse_query",
    "parse_suite",
    "query_key",
]
