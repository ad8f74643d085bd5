"""The worlds shipped with the package (``roboscript/worlds/*.yaml``), by name."""

from __future__ import annotations

from pathlib import Path

from roboscript.datafile import PackagedFiles
from roboscript.sim.world_file import WorldSpec, load_world_file

WORLDS = PackagedFiles("worlds", "world", others="")


def world_names() -> list[str]:
    """Names of the packaged worlds, sorted."""
    return WORLDS.names()


def world_path(name: str) -> Path:
    """The file of packaged world ``name``; raises ``KeyError`` naming the valid worlds."""
    return WORLDS.path(name, n=3)


def load_world(name_or_path: str | Path) -> WorldSpec:
    """A packaged world by name, or any world file by path (anything ending in .yaml/.yml/.json)."""
    return load_world_file(WORLDS.path(name_or_path, n=3))
