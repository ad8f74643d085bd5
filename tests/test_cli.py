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

    from roboscript.bench.benchmark import progress_printer
    from roboscript.bench.trial import TrialRecord

    stream = io.StringIO()
    report = progress_printer(2, stream)
    failed = {"check": "in(apple, footed_bowl)", "passed": False, "detail": ""}
    report(TrialRecord("simple_0", "panda", 0, 0, True, None, [failed], outcome="checks_failed"))
    report(TrialRecord("simple_0", "panda", 1, 1, True, None, [{**failed, "passed": True}]))
    first, second = stream.getvalue().splitlines()
    assert "0/1 checks, checks failed" in first and "1/1 checks, ok" in second
