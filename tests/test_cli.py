import json
import subprocess
import sys

import numpy as np
from PIL import Image

from roboscript.cli.main import main


def test_worlds_lists_the_six_worlds(capsys):
    assert main(["worlds"]) == 0
    out = capsys.readouterr().out
    assert out.count("\nworld_") + out.startswith("world_") >= 6 and "cabinet.drawer_1" in out
    assert "white_ceramic_plate" in out and "cluttered_1_table_sort" in out


def test_objects_lists_at_least_40_types_with_category_colour_and_shape(capsys):
    assert main(["objects"]) == 0
    rows = [line for line in capsys.readouterr().out.splitlines()[1:] if line.strip()]
    assert len(rows) >= 40
    assert any(r.startswith("footed_bowl") and " bowl " in r and "(container, not picked)" in r for r in rows)
    assert any(r.startswith("white_mug") and " mug " in r and r.endswith("(container)") for r in rows)
    assert any(r.startswith("soup_can") and " cylinder " in r and not r.endswith(")") for r in rows)


def test_render_writes_every_camera_and_a_top_view(tmp_path):
    out = tmp_path / "render"
    result = subprocess.run(
        [
            sys.executable,
            "-m",
            "roboscript.cli",
            "render",
            "world_2_pick_and_place",
            "--robot",
            "ur5e",
            "--out",
            str(out),
            "--settle",
            "0.2",
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert result.returncode == 0, result.stderr
    meta = json.loads((out / "cameras.json").read_text())
    assert meta["robot"] == "ur5e" and set(meta["cameras"]) == {"camera_left", "camera_right", "camera_top"}
    for camera in meta["cameras"]:
        rgb = np.asarray(Image.open(out / f"{camera}_rgb.png"))
        depth = np.asarray(Image.open(out / f"{camera}_depth.png"))
        assert rgb.shape == (480, 640, 3) and depth.dtype == np.uint16 and depth.max() > 500
        assert (out / f"{camera}_seg.png").is_file()
        seg = np.load(out / f"{camera}_seg.npy")
        names = {meta["segmentation_ids"][str(i)] for i in np.unique(seg) if i >= 0}
        assert "apple" in names or camera != "camera_top"
    assert (out / "top_view.png").is_file() and (out / "overview.png").is_file()


def test_bad_world_file_fails_with_its_message(tmp_path, capsys):
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: w\nobjects:\n  - {name: a, type: teapot, position: [0, 0]}\n")
    assert main(["render", str(bad), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert "bad.yaml" in err and "objects[0] 'a'" in err and "unknown object type 'teapot'" in err


def test_the_commands_offer_every_robot_there_is():
    from roboscript.cli.options import ROBOT_NAMES
    from roboscript.robots import ROBOTS

    assert sorted(ROBOT_NAMES) == sorted(ROBOTS)


def test_the_command_line_imports_what_a_command_runs_only_when_it_runs():
    """Importing the command line imports neither the simulator nor the benchmark: a command's implementation is
    imported when the command runs."""
    heavy = "('mujoco', 'roboscript.bench.trial', 'roboscript.assembly', 'scipy')"
    probe = f"import sys; import roboscript.cli.main; print(sorted(m for m in {heavy} if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_the_tool_reference_in_the_docs_is_what_the_llm_is_shown(capsys):
    from pathlib import Path

    assert main(["tools"]) == 0
    printed = capsys.readouterr().out.strip()
    page = (Path(__file__).resolve().parents[1] / "docs" / "tool_reference.md").read_text()
    assert printed in page and "def parse_place_pose(" in printed  # regenerate: roboscript tools


def test_version_and_a_closed_pipe_end_quietly():
    version = subprocess.run([sys.executable, "-m", "roboscript.cli", "--version"], capture_output=True, text=True)
    assert version.returncode == 0 and version.stdout.startswith("roboscript ")
    piped = subprocess.run(
        f"{sys.executable} -m roboscript.cli objects | head -1", shell=True, capture_output=True, text=True
    )
    assert piped.stdout.startswith("type") and "Traceback" not in piped.stderr and "BrokenPipe" not in piped.stderr


def test_a_trial_that_ran_but_failed_its_checks_is_not_reported_ok():
    import io

    from roboscript.bench.progress import ProgressBar, progress_printer
    from roboscript.bench.trial import TrialRecord

    stream = io.StringIO()
    report = progress_printer(2, stream)
    failed = {"check": "in(apple, footed_bowl)", "passed": False, "detail": ""}
    report(TrialRecord("simple_0", "panda", 0, 0, True, None, [failed], outcome="checks_failed"))
    report(TrialRecord("simple_0", "panda", 1, 1, True, None, [{**failed, "passed": True}]))
    first, second = stream.getvalue().splitlines()
    assert "0/1 checks, checks failed" in first and "1/1 checks, ok" in second
    bar_stream = io.StringIO()
    bar = ProgressBar(1, stream=bar_stream)
    bar.update(TrialRecord("simple_0", "panda", 0, 0, True, None, [failed], outcome="checks_failed"))
    assert bar_stream.getvalue().rstrip().endswith("simple_0 #0: checks failed")


def test_help_gives_every_options_default_and_what_the_exit_status_means(capsys):
    import pytest

    shown = {}
    for command in ("exec", "bench"):
        with pytest.raises(SystemExit):
            main([command, "--help"])
        shown[command] = " ".join(capsys.readouterr().out.split())  # argparse wraps lines anywhere
    assert "how many trials, each with its own seed (default: 1)" in shown["exec"]
    assert "how many trials, each with its own seed (default: 10)" in shown["bench"]
    assert "--seed SEED trial i uses seed + i for the world's randomisation (default: 0)" in shown["exec"]
    assert "the arm (default: panda)" in shown["exec"] and "(default: none)" in shown["bench"]  # --videos
    assert "exit status: 0 when every trial passed its task's checks" in shown["exec"]
    assert "1 when one did not, 2 for a usage error or a missing optional part" in shown["bench"]


def test_a_missing_extra_is_a_usage_error_with_its_install_command_before_any_trial(tmp_path, monkeypatch, capsys):
    from roboscript import extras
    from roboscript.bench.runner import TrialPool

    program = tmp_path / "program.py"
    program.write_text("open_gripper()\n")
    real = extras.installed
    # Test doubles: the perception and record extras look absent, and a trial that starts is noted, not run.
    monkeypatch.setattr(extras, "installed", lambda name: name not in ("perception", "record") and real(name))
    started = []
    monkeypatch.setattr(TrialPool, "run", lambda self, specs, *a, **k: started.extend(specs) or [])
    exec_ = ["exec", str(program), "--task", "simple_0"]
    assert main([*exec_, "--perception", "full"]) == 2
    error = capsys.readouterr().err
    assert error.startswith("roboscript: error: --perception full needs Open3D") and "Traceback" not in error
    assert f"install it with: {extras.install_hint('perception')}" in error
    assert main([*exec_, "--record", str(tmp_path / "trial.mcap")]) == 2
    assert "--record needs mcap (MCAP recordings), which is not installed" in capsys.readouterr().err
    assert main(["bench", "--tasks", "simple_0", "--perception", "gt-2d", "--out", str(tmp_path / "b")]) == 2
    assert "--perception gt-2d needs Open3D" in capsys.readouterr().err
    assert started == [] and not (tmp_path / "b").exists()


def test_the_install_hint_in_a_clone_is_the_clones_own_pip(monkeypatch):
    from roboscript import extras

    root = extras.source_checkout()
    assert root is not None and (root / "pyproject.toml").is_file()  # the tests run from a clone
    monkeypatch.chdir(root)
    monkeypatch.setattr(sys, "executable", str(root / ".venv" / "bin" / "python"))
    assert extras.install_hint("perception") == ".venv/bin/pip install -e '.[perception]'"
    monkeypatch.chdir("/")
    assert extras.install_hint("record") == f"{root}/.venv/bin/pip install -e '{root}[record]'"


def test_bench_exits_1_when_a_trial_fails_and_keeps_the_videos_of_the_failures(tmp_path):
    programs = tmp_path / "programs"
    programs.mkdir()
    (programs / "simple_0.py").write_text("open_gripper()\n")  # runs, and leaves the apple where it is
    out = tmp_path / "run"
    command = [sys.executable, "-m", "roboscript.cli", "bench", "--tasks", "simple_0", "--videos", "failed"]
    failing = [*command, "--policy", f"programs:{programs}", "--trials", "2", "--jobs", "2", "--out", str(out)]
    run = subprocess.run(failing, capture_output=True, text=True, timeout=600)
    assert run.returncode == 1, run.stderr
    assert sorted(p.name for p in (out / "videos").iterdir()) == ["simple_0_trial0.mp4", "simple_0_trial1.mp4"]
    assert f"videos in {out / 'videos'}" in run.stdout
    assert "2/2 100% | ok 0 failed 2 |" in run.stderr and "simple_0 #1: checks failed" in run.stderr
    passing = [*command, "--trials", "1", "--jobs", "1", "--out", str(tmp_path / "reference")]
    run = subprocess.run(passing, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    assert not list((tmp_path / "reference" / "videos").glob("*.mp4"))  # a success keeps no video


def test_a_refused_bench_leaves_no_run_folder_behind(tmp_path, capsys):
    import pytest

    from roboscript.bench.benchmark import run_benchmark
    from roboscript.errors import InvalidArgumentError

    out = tmp_path / "run"
    for bad in (["--trials", "0"], ["--jobs", "0"], ["--timeout", "0"]):
        with pytest.raises(SystemExit) as exit_:
            main(["bench", "--tasks", "simple_0", "--out", str(out), *bad])
        assert exit_.value.code == 2
        assert f"argument {bad[0]}: must be" in capsys.readouterr().err
    for trials, jobs, timeout in ((0, 1, 60.0), (1, 0, 60.0), (1, 1, 0.0)):
        with pytest.raises(InvalidArgumentError):
            run_benchmark("reference", ["simple_0"], "panda", trials, 0, out, jobs, timeout, progress=False)
    assert not out.exists()  # a later run with other settings is not refused for a run that never was


def test_a_runs_pace_is_given_in_trials_an_hour():
    from roboscript.cli.trial_output import throughput

    assert throughput(80, 195.0, 2) == "80 trials in 195 s: 1,477 trials an hour with 2 jobs"
    assert throughput(1, 9.0) == "1 trial in 9 s: 400 trials an hour"
