"""Study files: task templates written once for any object, and the grasp tools a study compares.

A study file (``roboscript/study/<name>.yaml``, or any file by path) names its templates; each gives an
instruction, a world (the studied object alone with the template's other objects and furniture), checks and a
reference program, with ``$object`` (the object's library type, which is also its name in the world), ``$words``
(the name in words) and ``$grasp`` (the grasp tool's call) standing for what changes from cell to cell. Every problem
is a :class:`StudyFileError` that names the file, the entry and what is wrong.
"""

from __future__ import annotations

from dataclasses import dataclass
from string import Template
from typing import Any

from roboscript.datafile import DataFileError, PackagedFiles, Reader, read_data_file
from roboscript.errors import UnknownNameError, unknown_name
from roboscript.objects import object_types
from roboscript.objects.library import OBJECT_LISTING

PLACEHOLDERS = ("object", "words", "grasp")
_STUDY_FIELDS = {"study", "description", "objects", "grasps", "templates"}
_TEMPLATE_FIELDS = {"id", "instruction", "world", "checks", "program"}
_WORLD_FIELDS = {"robot", "furniture", "objects", "subject", "randomize", "cameras", "table"}


class StudyFileError(DataFileError):
    """A study file that cannot be loaded; the message names the file, the entry and the problem."""

    kind = "study"


@dataclass(frozen=True)
class TaskTemplate:
    """One task written for any object: the parsed YAML of its world and checks, and its program's text, with
    placeholders still in them (:meth:`instantiate` fills them)."""

    id: str
    instruction: str
    world: dict
    checks: tuple[Any, ...]
    program: str

    def instantiate(self, object_name: str, grasp_call: str) -> tuple[str, dict, list, str]:
        """``(instruction, world data, checks data, program)`` for ``object_name`` grasped by ``grasp_call``."""
        values = {"object": object_name, "words": object_name.replace("_", " ")}
        values["grasp"] = Template(grasp_call).substitute(values)
        world = _fill(self.world, values)
        subject = world.pop("subject")
        world["objects"] = [*world.get("objects", []), {"name": object_name, "type": object_name, "position": subject}]
        return (
            Template(self.instruction).substitute(values),
            world,
            _fill(list(self.checks), values),
            Template(self.program).substitute(values),
        )


@dataclass(frozen=True)
class Study:
    """A study: its templates, the grasp tools it compares (name -> call) and the objects it runs over."""

    name: str
    description: str
    source: str
    templates: tuple[TaskTemplate, ...]
    grasps: dict[str, str]
    objects: tuple[str, ...]

    def template(self, template_id: str) -> TaskTemplate:
        return choose({t.id: t for t in self.templates}, template_id, "template")


def _fill(data: Any, values: dict[str, str]) -> Any:
    if isinstance(data, str):
        return Template(data).substitute(values)
    if isinstance(data, list):
        return [_fill(v, values) for v in data]
    if isinstance(data, dict):
        return {k: _fill(v, values) for k, v in data.items()}
    return data


def choose(options: dict, key: str, kind: str):
    """``options[key]``; a ``KeyError`` naming the closest keys and all of them where there is none."""
    if key not in options:
        raise UnknownNameError(unknown_name(kind, key, options, f"{kind}s: {', '.join(options)}", n=2))
    return options[key]


def _check_placeholders(reader: Reader, field: str, data: Any) -> None:
    """Every ``$name`` in ``data`` is a known placeholder (a typo would otherwise surface only when a cell runs)."""
    if isinstance(data, str):
        template = Template(data)
        if not template.is_valid():
            reader.fail(f"{field}: a '$' that starts no placeholder in {data!r}; write '$$' for a dollar sign")
        unknown = sorted(set(template.get_identifiers()) - set(PLACEHOLDERS))
        if unknown:
            reader.fail(f"{field}: unknown placeholder ${unknown[0]}; placeholders: ${', $'.join(PLACEHOLDERS)}")
    elif isinstance(data, list):
        for item in data:
            _check_placeholders(reader, field, item)
    elif isinstance(data, dict):
        for item in data.values():
            _check_placeholders(reader, field, item)


def _parse_template(source: str, index: int, data: Any) -> TaskTemplate:
    label = f"templates[{index}]" + (f" {data['id']!r}" if isinstance(data, dict) and "id" in data else "")
    entry = Reader(source, label, data, _TEMPLATE_FIELDS, StudyFileError)
    world = Reader(source, f"{label}.world", entry.required("world"), _WORLD_FIELDS, StudyFileError)
    world.vector("subject", (2,))
    checks = entry.required("checks")
    if not isinstance(checks, list) or not checks:
        entry.fail("field 'checks' must be a non-empty list, e.g. [{in: [$object, basket]}]")
    for field in ("instruction", "program"):
        entry.string(field)
    for field in ("instruction", "world", "checks", "program"):
        _check_placeholders(entry, field, data[field])
    if "$grasp" not in data["program"] and "${grasp}" not in data["program"]:
        entry.fail("the program never uses $grasp, so the study's grasp tools would all run the same program")
    return TaskTemplate(entry.string("id"), data["instruction"], dict(world.data), tuple(checks), data["program"])


def parse_study(data: Any, source: str = "<memory>") -> Study:
    """Validates a study given as parsed YAML/JSON data; raises :class:`StudyFileError`. The templates' worlds and
    checks are validated when cells are made from them (:mod:`roboscript.study.cells`)."""
    entry = Reader(source, "study", data, _STUDY_FIELDS, StudyFileError)
    grasps = entry.required("grasps")
    if not isinstance(grasps, dict) or not grasps or not all(isinstance(v, str) for v in grasps.values()):
        entry.fail("field 'grasps' must map grasp tool names to their calls, e.g. {central: \"parse_...('$object')\"}")
    for name, call in grasps.items():
        _check_placeholders(entry, f"grasps.{name}", call)
    items = entry.required("templates")
    if not isinstance(items, list) or not items:
        entry.fail("field 'templates' must be a non-empty list of templates")
    templates = tuple(_parse_template(source, i, t) for i, t in enumerate(items))
    ids = [t.id for t in templates]
    if len(set(ids)) != len(ids):
        entry.fail(f"template ids must be unique, got {ids}")
    return Study(
        name=entry.string("study"),
        description=entry.text("description"),
        source=source,
        templates=templates,
        grasps=dict(grasps),
        objects=_parse_objects(entry, data.get("objects", "pickable")),
    )


def _parse_objects(entry: Reader, value: Any) -> tuple[str, ...]:
    """``pickable`` (every type a task picks up) or a list of the library's types."""
    library = object_types()
    if value == "pickable":
        return tuple(name for name, t in library.items() if t.pickable)
    if not isinstance(value, list) or not value:
        entry.fail(f"field 'objects' must be 'pickable' or a non-empty list of object types, got {value!r}")
    for name in value:
        if name not in library:
            entry.fail("objects: " + unknown_name("object type", name, library, OBJECT_LISTING))
    return tuple(value)


STUDIES = PackagedFiles("study", "study", others="or a file")


def study_names() -> list[str]:
    """The packaged studies."""
    return STUDIES.names()


def load_study(name_or_path: str) -> Study:
    """A packaged study by name (``objects``), or a study file by path."""
    path = STUDIES.path(name_or_path)
    return parse_study(read_data_file(path, StudyFileError), str(path))
