"""Data files (worlds, task suites): reading YAML or JSON, and typed access to their entries with errors that name
the file, the entry and the problem."""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any, ClassVar, NoReturn

import yaml

from roboscript.errors import UnknownNameError, UsageError, did_you_mean, unknown_name

DATA_SUFFIXES = (".yaml", ".yml", ".json")


class DataFileError(UsageError, ValueError):
    """A data file that cannot be loaded: ``<kind> file <source>: <entry>: <problem>``."""

    kind: ClassVar[str] = "data"

    def __init__(self, source: str, entry: str, problem: str):
        self.source, self.entry, self.problem = source, entry, problem
        super().__init__(f"{self.kind} file {source}: {entry}: {problem}")

    def __reduce__(self):
        # Pickled as its three parts, so that it crosses from a worker process intact (the default pickles the
        # message alone, which this constructor does not take).
        return (type(self), (self.source, self.entry, self.problem))


class Reader:
    """Typed access to one mapping of a data file; every problem raises ``error`` saying where."""

    def __init__(self, source: str, entry: str, data: Any, allowed: set[str], error: type[DataFileError]):
        self.source, self.entry, self.error = source, entry, error
        if not isinstance(data, dict):
            self.fail(f"expected a mapping, got {type(data).__name__} {data!r}")
        unknown = sorted(str(k) for k in set(data) - allowed)
        if unknown:
            close = did_you_mean(unknown[0], allowed, n=1, cutoff=0.6, quoted=True)
            hint = f" ({close})" if close else ""
            self.fail(f"unknown field {unknown[0]!r}{hint}; valid fields: {', '.join(sorted(allowed))}")
        self.data = data

    def fail(self, problem: str) -> NoReturn:
        raise self.error(self.source, self.entry, problem)

    def required(self, key: str) -> Any:
        if key not in self.data:
            self.fail(f"missing required field {key!r}")
        return self.data[key]

    def string(self, key: str, default: str | None = None) -> str:
        """A non-empty string; ``default`` where the field is absent (required when there is none)."""
        value = self.data.get(key, default) if default is not None else self.required(key)
        if not isinstance(value, str) or not value.strip():
            self.fail(f"field {key!r} must be a non-empty string, got {value!r}")
        return value

    def text(self, key: str) -> str:
        """An optional string field (a description): empty where absent."""
        value = self.data.get(key, "")
        if not isinstance(value, str):
            self.fail(f"field {key!r} must be text, got {type(value).__name__} {value!r}")
        return value

    def number(self, key: str, default: float | None = None) -> float:
        """A finite number; ``default`` where the field is absent (required when there is none)."""
        value = self.data.get(key, default) if default is not None else self.required(key)
        if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
            self.fail(f"field {key!r} must be a finite number, got {value!r}")
        return float(value)

    def vector(self, key: str, lengths: tuple[int, ...], default: tuple[float, ...] | None = None) -> tuple:
        value = self.data.get(key, default) if default is not None else self.required(key)
        ok = isinstance(value, list | tuple) and len(value) in lengths
        ok = ok and all(isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v) for v in value)
        if not ok:
            shapes = " or ".join(f"a list of {n} numbers" for n in lengths)
            self.fail(f"field {key!r} must be {shapes}, got {value!r}")
        return tuple(float(v) for v in value)


def entry_label(field: str, index: int, item: Any, key: str = "name") -> str:
    """How an error names the ``index``-th entry of a list ``field``: ``objects[2] 'apple'`` where the entry has
    its ``key``, ``objects[2]`` where it has none yet."""
    label = f"{field}[{index}]"
    if isinstance(item, dict) and isinstance(item.get(key), str):
        label += f" {item[key]!r}"
    return label


class _Yaml12Loader(yaml.SafeLoader):
    """YAML with YAML 1.2 booleans: only true/false. YAML 1.1 would read the key ``on:`` as ``True``."""


_Yaml12Loader.yaml_implicit_resolvers = {
    first: [(tag, regexp) for tag, regexp in resolvers if tag != "tag:yaml.org,2002:bool"]
    for first, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()
}
_Yaml12Loader.add_implicit_resolver(
    "tag:yaml.org,2002:bool",
    re.compile(r"^(?:true|True|TRUE|false|False|FALSE)$"),
    list("tTfF"),
)


def load_yaml(text: str):
    """Parses YAML text with YAML 1.2 booleans (see :class:`_Yaml12Loader`)."""
    return yaml.load(text, Loader=_Yaml12Loader)


def read_data_file(path: str | Path, error: type[DataFileError]) -> Any:
    """The parsed contents of a ``.yaml``/``.yml``/``.json`` file; ``error`` if it is missing or does not parse."""
    path = Path(path)
    if not path.is_file():
        raise error(str(path), "file", "does not exist")
    text = path.read_text()
    try:
        return json.loads(text) if path.suffix == ".json" else load_yaml(text)
    except (yaml.YAMLError, json.JSONDecodeError) as exc:
        raise error(str(path), "file", f"is not valid {path.suffix.lstrip('.').upper()}: {exc}") from exc


@dataclass(frozen=True)
class PackagedFiles:
    """The data files of one kind that the package ships (``roboscript/<folder>/*.yaml``: worlds, suites, studies,
    recipes, robot configurations): each found by its name, and any file of the kind by its path."""

    folder: str
    kind: str  # what one is called in a refusal: "world", "suite"
    others: str = "or a file's path"  # what else a refusal says is valid

    def directory(self) -> Path:
        return Path(str(resources.files("roboscript") / self.folder))

    def names(self) -> list[str]:
        """The packaged ones' names, sorted."""
        return sorted(p.stem for p in self.directory().glob("*.yaml"))

    def path(self, reference: str | Path, names: list[str] | None = None, n: int = 2, cutoff: float = 0.4) -> Path:
        """The file ``reference`` names: itself where it is a file's path, else the packaged one of that name;
        :class:`~roboscript.errors.UnknownNameError` with the closest names where there is none (``names``: the
        packaged ones in the order a refusal lists them)."""
        if names_a_file(reference):
            return Path(reference)
        path = self.directory() / f"{reference}.yaml"
        if not path.is_file():
            names = self.names() if names is None else names
            listing = f"{self.kind}s: {', '.join(names)}" + (f", {self.others}" if self.others else "")
            raise UnknownNameError(unknown_name(self.kind, reference, names, listing, n=n, cutoff=cutoff))
        return path


def names_a_file(reference: str | Path) -> bool:
    """Whether a name given for a world or a suite is a file's path rather than a packaged one's name."""
    text = str(reference)
    return text.endswith(DATA_SUFFIXES) or Path(text).is_file()
