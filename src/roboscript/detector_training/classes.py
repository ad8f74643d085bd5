"""The classes the detector tells apart: the object library's types, those that look alike joined into one.

Two types look alike when they are built of the same parts in the same colours (a white mug and a white porcelain
mug): no camera can tell them apart, so one class stands for both, named by their type names joined with ``+``.
Then come furniture (carcasses, fronts, drawers' insides), handles, and other (what is no object: the robot's
fringe, glimpses of the table's edge).
"""

from __future__ import annotations

from roboscript.objects import object_types
from roboscript.perception.detection.detector_model import FURNITURE, HANDLE, OTHER


def _looks(type_name: str) -> tuple:
    kind = object_types()[type_name]
    parts = tuple((p.kind, p.size, p.pos, p.quat, p.rgba or kind.rgba) for p in kind.parts)
    return (parts, kind.rgba)


def look_alike_classes(types: list[str] | None = None) -> dict[str, str]:
    """Each type (of ``types``, all the library's by default) to the name of its class."""
    names = sorted(types if types is not None else object_types())
    groups: dict[tuple, list[str]] = {}
    for name in names:
        groups.setdefault(_looks(name), []).append(name)
    return {name: "+".join(group) for group in groups.values() for name in group}


def class_names(class_of_type: dict[str, str]) -> list[str]:
    """The classes in the model's order: objects' (sorted), then furniture, handle, other."""
    return [*sorted(set(class_of_type.values())), FURNITURE, HANDLE, OTHER]
