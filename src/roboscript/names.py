"""What a name stands for, read from the name alone.

Furniture parts are named ``<furniture>.<kind>_<index>`` (``cabinet.drawer_1``, ``cabinet.handle_1``), as the
original benchmark names them; the table is ``table``. An object and a whole piece of furniture (``cabinet``)
cannot be told apart by name: ask perception which names are objects.
"""

from __future__ import annotations

from typing import Literal

TABLE = "table"  # the table is an object to every tool, as the original benchmark's queries list it

Kind = Literal["table", "drawer", "door", "handle", "other"]
PART_KINDS: tuple[Kind, ...] = ("drawer", "door", "handle")


def kind_of(name: str) -> Kind:
    """``"drawer"``, ``"door"`` or ``"handle"`` for a furniture part, ``"table"`` for the table, ``"other"`` for
    an object or a whole piece of furniture."""
    if name == TABLE:
        return "table"
    _, dot, part = name.rpartition(".")
    if dot:
        for part_kind in PART_KINDS:
            if part.startswith(part_kind + "_"):
                return part_kind
    return "other"


def is_part(name: str) -> bool:
    """Whether ``name`` is a part of furniture (a drawer, door or handle)."""
    return kind_of(name) in PART_KINDS
