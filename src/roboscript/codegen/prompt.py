"""Prompts: the rules, the tool API's own signatures and doc-strings (one source of truth), few-shot examples.

Few-shot examples are files in ``examples/``: a first line ``# query: objects = [...] ; # instruction``, then the
program, planning comments first.
"""

from __future__ import annotations

import inspect
from collections.abc import Sequence
from dataclasses import dataclass
from importlib import resources

from roboscript.api import ToolAPI
from roboscript.api.program_errors import PROGRAM_ERRORS

RULES = """You write Python programs that make a robot arm with a parallel gripper do a task on a table.
Rules:
- Start with comments: the task, then a numbered plan, step by step. Then the code.
- Use only the tools below, `np` (numpy) and `Pose`. Do not import anything; there is no file or network access.
- Refer to objects by the names in the query. Parts of furniture are numbered from the top down:
  `cabinet.drawer_0` is the top drawer, `cabinet.door_0` the top door, and `cabinet.handle_k` is the handle on the
  k-th row from the top, drawers and doors counted together (in a cabinet of two drawers above a door,
  `cabinet.handle_1` is the second drawer's and `cabinet.handle_2` the door's); the query lists a cabinet's drawers
  and doors row by row from the top, whatever their kind (a door above a drawer is listed first). The table
  and the furniture are objects too (`get_3d_bbox('table')`, `parse_place_pose(name, 'table')`), and
  `get_object_name_list()` lists them: leave out `table`, `cabinet` and its parts when you mean the things on
  the table.
- Plates, saucers, bowls and baskets stay where they are: things go in or on them, and the gripper cannot pick
  them up.
- Positions are in metres in the world's frame, whose axes are the robot's: x forward (away from the robot), y
  left, z up. Its origin is not the robot's base{base}.
- To pick something: open_gripper(), grasp(a grasp pose), close_gripper(), attach_object(name), then lift it.
- To put something down: move_to_pose(a place pose), open_gripper(), detach_object(name), then move up.
- Drawers and doors: grasp the handle, close the gripper, attach the drawer or door, then move along its joint.
- Answer with one Python code block and nothing else."""

FUNCTION_RULES = """You write one Python function for a robot program, using the same tools as the program.
Answer with one Python code block holding the function's definition (and any helpers it needs), nothing else."""


def _kinds_of(root: str) -> str:
    """The program errors under the one named ``root``, each with the one it is a kind of where that is not
    ``root`` (``IKError is a PlanningError``)."""
    kinds = []
    for name, cls in PROGRAM_ERRORS.items():
        if name != root and issubclass(cls, PROGRAM_ERRORS[root]):
            parent = next(b.__name__ for b in cls.__mro__[1:] if b.__name__ in PROGRAM_ERRORS)
            kinds.append(name if parent == root else f"{name} is a {parent}")
    return ", ".join(kinds)


def tool_reference() -> str:
    """Every tool as ``def name(args):`` with its doc-string, in the API's order."""
    blocks = []
    for name in ToolAPI.TOOL_NAMES:
        method = getattr(ToolAPI, name)
        doc = inspect.getdoc(method) or ""
        indented = "\n".join("    " + line if line else "" for line in doc.splitlines())
        blocks.append(f'def {method.usage}:\n    """\n{indented}\n    """')
    pose = "Pose(): a pose with .position.x/.y/.z and .orientation.x/.y/.z/.w (a unit quaternion), all assignable."
    errors = (
        f"Errors a program may catch by name: {', '.join(PROGRAM_ERRORS)}; FailureError is any the robot could not "
        f"do ({_kinds_of('FailureError')}), UsageError any call that was wrong ({_kinds_of('UsageError')}). A program "
        "that gives up raises one with a message, e.g. raise PlacementError('no free spot on the plate')."
    )
    return "\n\n".join(blocks) + "\n\n# " + pose + "\n# " + errors


def system_prompt(base_xy: Sequence[float] | None = None) -> str:
    """The rules and the tools. ``base_xy``: where the robot's base stands (x, y), said in the rules where known:
    a program that chooses spots by the arm's reach needs it, and the world's origin is elsewhere."""
    where = "" if base_xy is None else f", which stands at x = {base_xy[0]:.2f}, y = {base_xy[1]:.2f}"
    return f"{RULES.replace('{base}', where)}\n\nTools:\n\n```python\n{tool_reference()}\n```"


@dataclass(frozen=True)
class Example:
    name: str
    query: str
    program: str


def load_examples() -> list[Example]:
    """The few-shot examples shipped with the package, in file-name order."""
    examples = []
    folder = resources.files("roboscript.codegen") / "examples"
    for entry in sorted(folder.iterdir(), key=lambda e: e.name):
        if not entry.name.endswith(".py"):
            continue
        text = entry.read_text()
        first, _, program = text.partition("\n")
        if not first.startswith("# query: "):
            raise ValueError(f"example {entry.name} must start with '# query: objects = [...] ; # instruction'")
        examples.append(Example(entry.name, first.removeprefix("# query: ").strip(), program.strip() + "\n"))
    return examples


def task_query(objects: list[str], instruction: str) -> str:
    """``objects = [table, cabinet, apple] ; # instruction``: the original benchmark's query form, which the
    examples use too."""
    return f"objects = [{', '.join(objects)}] ; # {instruction.strip()}"


def fenced(program: str) -> str:
    return f"```python\n{program.rstrip()}\n```"


def program_messages(
    query: str, examples: list[Example] | None = None, base_xy: Sequence[float] | None = None
) -> list[dict]:
    """System prompt (:func:`system_prompt`), the examples as earlier turns, then the query."""
    examples = load_examples() if examples is None else examples
    messages = [{"role": "system", "content": system_prompt(base_xy)}]
    for example in examples:
        messages.append({"role": "user", "content": example.query})
        messages.append({"role": "assistant", "content": fenced(example.program)})
    messages.append({"role": "user", "content": query})
    return messages


def function_messages(name: str, call: str, program: str) -> list[dict]:
    """Asks for the definition of ``name``, called as in ``call`` within ``program``."""
    request = (
        f"This program calls `{name}`, which is not defined yet:\n\n{fenced(program)}\n\n"
        f"It is called as `{call}`. Write `def {name}(...)` so that this call does what the program needs."
    )
    return [
        {"role": "system", "content": f"{FUNCTION_RULES}\n\nTools:\n\n```python\n{tool_reference()}\n```"},
        {"role": "user", "content": request},
    ]


def repair_messages(
    query: str,
    program: str,
    errors: list[str],
    examples: list[Example] | None = None,
    base_xy: Sequence[float] | None = None,
) -> list[dict]:
    """The original conversation, the program as the model's answer, then the errors and a request to fix them."""
    messages = program_messages(query, examples, base_xy)
    messages.append({"role": "assistant", "content": fenced(program)})
    listed = "\n".join(f"- {e}" for e in errors)
    messages.append(
        {"role": "user", "content": f"The program has these errors:\n{listed}\nWrite the corrected program, whole."}
    )
    return messages
