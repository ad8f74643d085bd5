"""What a reader of a query makes of a thing's name: its colour and its kind, as ``reading.yaml`` says.

A program sees names only. A task that sorts "the green objects" must mean the things whose names say green (or
whose colour every reader knows, a lime), not those the library happens to draw green (a tea box): the checks of
generated tasks are built from these readings.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from importlib import resources

from roboscript.datafile import DataFileError, Reader, read_data_file


class ReadingFileError(DataFileError):
    kind = "reading"


@dataclass(frozen=True)
class Readings:
    colours: tuple[str, ...]
    known_colours: dict[str, str]
    kinds: dict[str, tuple[str, ...]]


@cache
def readings() -> Readings:
    """The packaged ``reading.yaml``, validated."""
    path = resources.files("roboscript.objects") / "reading.yaml"
    data = read_data_file(str(path), ReadingFileError)
    top = Reader(str(path), "top level", data, {"colours", "known_colours", "kinds"}, ReadingFileError)
    colours = top.required("colours")
    known = top.required("known_colours")
    kinds = top.required("kinds")
    if not isinstance(colours, list) or not all(isinstance(c, str) for c in colours):
        top.fail(f"colours must be a list of colour words, got {colours!r}")
    if not isinstance(known, dict) or not all(isinstance(v, str) and v in colours for v in known.values()):
        top.fail(f"known_colours must map names to one of the colours ({', '.join(colours)}), got {known!r}")
    if not isinstance(kinds, dict) or not all(
        isinstance(words, list) and words and all(isinstance(w, str) for w in words) for words in kinds.values()
    ):
        top.fail(f"kinds must map a kind to a non-empty list of name words, got {kinds!r}")
    return Readings(tuple(colours), dict(known), {k: tuple(v) for k, v in kinds.items()})


def said_colour(name: str) -> str | None:
    """The one colour a reader gives ``name``: the colour word it says (``green_apple``), or the colour every
    reader knows it by (``lime``); None where it says none or two (``white_and_yellow_mug``)."""
    read = readings()
    words = name.split("_")
    said = {w for w in words if w in read.colours}
    if len(said) == 1:
        return said.pop()
    if said:
        return None
    return read.known_colours.get(name)


def said_kind(name: str) -> str | None:
    """The kind a reader gives ``name`` from its words (``tennis_ball``: a ball; ``rubiks_cube``: none)."""
    words = set(name.split("_"))
    return next((kind for kind, names in readings().kinds.items() if words & set(names)), None)
