"""The worlds shipped with the package (``roboscript/worlds/*.yaml``), by name."""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from roboscript.datafile import names_a_file
from roboscript.errors import UnknownNameError, unknown_name
from roboscript.sim.world_file import WorldSpec, load_world_file


def _world_dir() -> Path:
    return Path(str(resources.files("roboscript") / "worlds"))


def world_names() -> list[str]:
    """Names of the packaged worlds, sorted."""
    return sorted(p.stem for p in _world_dir().glob("*.yaml"))


def world_path(name: str) -> Path:
    """The file of packaged world ``name``; raises ``KeyError`` naming the valid worlds."""
    path = _world_dir() / f"{name}.yaml"
    if not path.is_file():
        names = world_names()
        raise UnknownNameError(unknown_name("world", name, names, f"valid worlds: {', '.join(names)}", cutoff=0.4))
    return path


def load_world(name_or_path: str | Path) -> WorldSpec:
    """A packaged world by name, or any world file by path (anything ending in .yaml/.yml/.json)."""
    if names_a_file(name_or_path):
        return load_world_file(name_or_path)
    return load_world_file(world_path(str(name_or_path)))
