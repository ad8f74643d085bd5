"""ROS 1 message and action types that Debian does not package (control_msgs, franka_gripper), built at run time.

Their definitions ship with this package (``definitions/PKG/NAME.msg|.action``). An action definition becomes its
seven messages (``NAMEGoal``, ``NAMEActionGoal``, ... ``NAMEAction``), as ROS's build would make them, and genpy
compiles the classes from the definitions' text. Field names and types are the upstream ones, so the MD5 sums match
those real drivers check (``control_msgs/FollowJointTrajectoryAction``: ``bc4f9b74...``).
"""

from __future__ import annotations

import functools
import importlib
import sys
import types
from dataclasses import dataclass
from pathlib import Path

from roboscript.errors import UsageError

DEFINITIONS = Path(__file__).with_name("definitions")
SEPARATOR = "=" * 80
PRIMITIVES = frozenset(
    [
        "bool",
        "byte",
        "char",
        "int8",
        "uint8",
        "int16",
        "uint16",
        "int32",
        "uint32",
        "int64",
        "uint64",
        "float32",
        "float64",
        "string",
        "time",
        "duration",
    ]
)


class MessageDefinitionError(UsageError, LookupError):
    """A message type is neither shipped here nor installed, or its definition is malformed."""


@dataclass(frozen=True)
class ActionTypes:
    """The classes of one action: what an ``actionlib`` client or server is made with, and its parts."""

    action: type
    goal: type
    result: type
    feedback: type


def _action_parts(package: str, name: str, text: str) -> dict[str, str]:
    sections = text.split("\n---")
    if len(sections) != 3:
        raise MessageDefinitionError(f"{package}/{name}.action must have goal, result and feedback parted by ---")
    goal, result, feedback = (s.strip("\n") + "\n" for s in sections)
    return {
        f"{package}/{name}Goal": goal,
        f"{package}/{name}Result": result,
        f"{package}/{name}Feedback": feedback,
        f"{package}/{name}ActionGoal": f"Header header\nactionlib_msgs/GoalID goal_id\n{name}Goal goal\n",
        f"{package}/{name}ActionResult": f"Header header\nactionlib_msgs/GoalStatus status\n{name}Result result\n",
        f"{package}/{name}ActionFeedback": (
            f"Header header\nactionlib_msgs/GoalStatus status\n{name}Feedback feedback\n"
        ),
        f"{package}/{name}Action": (
            f"{name}ActionGoal action_goal\n{name}ActionResult action_result\n{name}ActionFeedback action_feedback\n"
        ),
    }


@functools.cache
def _shipped() -> dict[str, str]:
    """Every definition shipped here, by type name."""
    found: dict[str, str] = {}
    for path in sorted(DEFINITIONS.glob("*/*")):
        package, text = path.parent.name, path.read_text()
        if path.suffix == ".msg":
            found[f"{package}/{path.stem}"] = text
        elif path.suffix == ".action":
            found.update(_action_parts(package, path.stem, text))
    return found


def _definition(type_name: str) -> str:
    shipped = _shipped()
    if type_name in shipped:
        return shipped[type_name]
    package, _, name = type_name.partition("/")
    try:
        cls = getattr(importlib.import_module(f"{package}.msg"), name)
    except (ImportError, AttributeError):
        raise MessageDefinitionError(
            f"no definition of {type_name}: neither shipped in {DEFINITIONS} nor installed (apt install "
            f"python3-{package.replace('_', '-')})"
        ) from None
    return cls._full_text.split("\n" + SEPARATOR)[0]


def _dependencies(type_name: str, text: str) -> list[str]:
    package = type_name.split("/")[0]
    found = []
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if not line or "=" in line:  # blank, comment or constant
            continue
        field_type = line.split()[0].split("[")[0]
        if field_type in PRIMITIVES:
            continue
        if field_type == "Header":
            field_type = "std_msgs/Header"
        found.append(field_type if "/" in field_type else f"{package}/{field_type}")
    return found


def full_text(type_name: str) -> str:
    """``type_name``'s definition followed by those of every type it uses, as a bag or genpy expects them."""
    order, queue = [], [type_name]
    while queue:
        current = queue.pop(0)
        if current in order:
            continue
        order.append(current)
        queue.extend(_dependencies(current, _definition(current)))
    parts = [_definition(order[0])]
    parts += [f"{SEPARATOR}\nMSG: {t}\n{_definition(t)}" for t in order[1:]]
    return "\n".join(parts)


def _compile(core_type: str, text: str) -> dict[str, type]:
    """The classes of ``core_type`` and every type in its full ``text``, compiled in memory.

    genpy.dynamic does the same through a temporary directory it removes at exit, which a forked trial process
    (ended with os._exit) never reaches; so its steps are taken here without the file.
    """
    import genmsg
    import genmsg.msg_loader
    from genpy.dynamic import _gen_dyn_modify_references, _gen_dyn_name, _generate_dynamic_specs
    from genpy.generator import msg_generator

    core, *dependencies = text.split(f"\n{SEPARATOR}\n")
    context = genmsg.MsgContext.create_default()
    specs = {core_type: genmsg.msg_loader.load_msg_from_string(context, core, core_type)}
    for dependency in dependencies:
        name, spec = _generate_dynamic_specs(context, specs, dependency)
        specs[name] = spec
    context = genmsg.MsgContext.create_default()  # registered afresh, as dependents are generated against them
    for name, spec in specs.items():
        context.register(name, spec)
    source = "\n".join(
        _gen_dyn_modify_references(line, name, list(specs))
        for name, spec in specs.items()
        for line in msg_generator(context, spec, {})
    )
    module = types.ModuleType(f"roboscript_ros_generated_{core_type.replace('/', '_')}")
    exec(compile(source, f"<generated {core_type}>", "exec"), module.__dict__)
    sys.modules[module.__name__] = module
    classes = {}
    for name, spec in specs.items():
        cls = getattr(module, _gen_dyn_name(*genmsg.package_resource_name(name)))
        cls._spec = spec
        classes[name] = cls
    return classes


@functools.cache
def message_class(type_name: str) -> type:
    """The class of message ``type_name`` (``control_msgs/GripperCommand``)."""
    return _compile(type_name, full_text(type_name))[type_name]


@functools.cache
def action_types(action_name: str) -> ActionTypes:
    """The classes of action ``action_name`` (``control_msgs/FollowJointTrajectory``)."""
    classes = _compile(f"{action_name}Action", full_text(f"{action_name}Action"))
    return ActionTypes(
        classes[f"{action_name}Action"],
        classes[f"{action_name}Goal"],
        classes[f"{action_name}Result"],
        classes[f"{action_name}Feedback"],
    )
