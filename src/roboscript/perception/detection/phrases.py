"""What a phrase names, in the object library's words: the types a program may mean by ``'white_ceramic_plate'``,
``'plate'``, ``'white plate'``, ``'fruits'`` or ``'mug_1'``.

A phrase means every type it may name, each as specifically as it names it: as a name a scene's description gives
one of its objects (that type, then others of its category in its colours), as a type's name (``white_plate``), as a
colour with a category (``white plate`` names every white plate too), as a category (``plate``), as a group of
categories (``fruit``, :file:`phrase_groups.yaml`), with or without a colour (``red fruit``). The detector labels
with a phrase the most specifically named things it sees. Plurals and a trailing number (``boxes``, ``mug_1``) are
read as the word itself.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from dataclasses import dataclass
from importlib import resources

from roboscript.datafile import load_yaml
from roboscript.objects import object_types
from roboscript.perception.detection.grounding import normalize_phrase

DESCRIBED, NAME, COLOURED, CATEGORY, GROUP = 5, 4, 3, 2, 1  # how specifically a phrase names a type


@dataclass(frozen=True)
class PhraseMatch:
    """The types a phrase may mean, each with how specifically it names it (:data:`DESCRIBED` ...
    :data:`GROUP`)."""

    specificity: dict[str, int]

    @property
    def types(self) -> frozenset[str]:
        return frozenset(self.specificity)


@functools.cache
def phrase_groups() -> dict[str, frozenset[str]]:
    """Group word -> the categories it takes in; raises ``ValueError`` naming a category the library lacks."""
    text = (resources.files("roboscript") / "perception" / "detection" / "phrase_groups.yaml").read_text()
    data = load_yaml(text)
    categories = {normalize_phrase(t.category) for t in object_types().values()}
    groups = {}
    for word, members in data.items():
        unknown = sorted(set(members) - categories)
        if unknown:
            raise ValueError(f"phrase_groups.yaml: group {word!r} names unknown categories {unknown}")
        groups[normalize_phrase(word)] = frozenset(members)
    return groups


@functools.cache
def _vocabulary() -> dict[str, dict[str, int]]:
    """Every phrase the library answers to, with the types it names and how specifically."""
    words: dict[str, dict[str, int]] = {}

    def add(word: str, type_name: str, specificity: int) -> None:
        meanings = words.setdefault(word, {})
        meanings[type_name] = max(meanings.get(type_name, 0), specificity)

    groups = phrase_groups()
    for kind in object_types().values():
        category, colour = normalize_phrase(kind.category), normalize_phrase(kind.color)
        add(normalize_phrase(kind.name), kind.name, NAME)
        add(f"{colour} {category}", kind.name, COLOURED)
        add(category, kind.name, CATEGORY)
        for word, members in groups.items():
            if category in members:
                add(word, kind.name, GROUP)
                add(f"{colour} {word}", kind.name, GROUP)
    return words


def _readings(phrase: str) -> list[str]:
    """The phrase, without a trailing number, and in the singular."""
    words = normalize_phrase(phrase).split()
    out = [" ".join(words)]
    if len(words) > 1 and words[-1].isdigit():
        words = words[:-1]
        out.append(" ".join(words))
    if words:
        last = words[-1]
        for ending, replacement in (("ies", "y"), ("oes", "o"), ("ches", "ch"), ("xes", "x"), ("s", "")):
            if last.endswith(ending) and len(last) > len(ending) + 1:
                out.append(" ".join([*words[:-1], last[: -len(ending)] + replacement]))
                break
    return out


def _colours_of(kind) -> list[str]:
    """The colours a thing of type ``kind`` shows: its own, and those its name says (a white and yellow mug may
    look yellow where its handle fills the view)."""
    known = {normalize_phrase(t.color) for t in object_types().values()}
    named = [word for word in normalize_phrase(kind.name).split() if word in known]
    return list(dict.fromkeys([normalize_phrase(kind.color), *named]))


def match_phrase(phrase: str, described: Mapping[str, str] | None = None) -> PhraseMatch | None:
    """The types ``phrase`` names; ``described``: the scene description's object names and their types, which
    come first. None where it names nothing the library knows."""
    described = {normalize_phrase(n): t for n, t in (described or {}).items()}
    vocabulary = _vocabulary()
    for reading in _readings(phrase):
        if reading in described:
            # What the description calls it, first; then what looks like it (a white mug for a white-and-yellow
            # one whose handle was not seen), where nothing more like it is in sight.
            kind = object_types()[described[reading]]
            looser: dict[str, int] = {}
            for colour in _colours_of(kind):
                for t, level in vocabulary.get(f"{colour} {normalize_phrase(kind.category)}", {}).items():
                    looser[t] = max(looser.get(t, 0), min(level, COLOURED))
            return PhraseMatch({**looser, kind.name: DESCRIBED})
        if reading in vocabulary:
            return PhraseMatch(dict(vocabulary[reading]))
    return None
