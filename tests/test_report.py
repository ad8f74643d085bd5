"""``roboscript report``: runs found in sweep folders, the CSV, the plots (real PNGs) and the HTML page with every
failed trial and its video."""

import json
from pathlib import Path

from PIL import Image

from roboscript.bench.results import RunDirectory, provenance
from roboscript.bench.trial import TrialRecord
from roboscript.cli.main import main
from roboscript.report.runs import find_runs
from roboscript.report.write import write_report


def _run(folder: Path, perception: str, outcomes: dict[str, list[bool]]) -> Path:
    run = RunDirectory(folder, provenance("reference", "panda", 3, 0, {t: t for t in outcomes}, perception))
    for task, results in outcomes.items():
        for trial, success in enumerate(results):
            checks = [{"check": f"in({task}, bowl)", "passed": success, "detail": "detail"}]
            error = None if success else "GraspError: too wide"
            run.append(TrialRecord(task, "panda", trial, trial, success, error, checks,
                                   outcome="ok" if success else "planning_failure"))  # fmt: skip
    run.write_summary(list(outcomes))
    return folder


def test_a_report_of_a_sweep_folder_has_tables_plots_and_every_failure_with_its_video(tmp_path):
    sweep = tmp_path / "sweep"
    _run(sweep / "reference_panda_gt", "gt", {"simple_0": [True, True, True], "hard_2": [True, False, True]})
    _run(sweep / "reference_panda_gt-2d", "gt-2d", {"simple_0": [True, False, False], "hard_2": [False, True, True]})
    video = sweep / "reference_panda_gt" / "videos" / "hard_2_trial1.mp4"
    video.parent.mkdir()
    video.write_bytes(b"not really a video")
    out = tmp_path / "report"
    report = write_report([sweep], out)
    assert [r.label for r in report.runs] == ["reference · gt · panda", "reference · gt-2d · panda"]
    names = {p.name for p in report.files}
    assert {"report.md", "report.csv", "success_by_task.png", "success_by_run.png", "index.html"} <= names
    for png in out.glob("*.png"):
        with Image.open(png) as image:
            assert image.format == "PNG" and image.width > 400 and image.height > 200
    rows = (out / "report.csv").read_text().splitlines()
    assert rows[0].startswith("run,policy,perception,robot,task,trials,grammar_correctness")
    assert "reference_panda_gt-2d,reference,gt-2d,panda,simple_0,3,0.3333,1.0,0.3333,0.3333" in rows
    page = (out / "index.html").read_text()
    assert page.count('class="trial"') == 4  # one failure in the first run, three in the second
    assert '<video controls preload="metadata" src="../sweep/reference_panda_gt/videos/hard_2_trial1.mp4">' in page
    assert page.count("no video kept") == 3
    assert "GraspError: too wide" in page and "success_by_task.png" in page


def test_runs_of_the_same_settings_are_told_apart_and_a_folder_without_runs_is_refused(tmp_path):
    _run(tmp_path / "a" / "reference_panda_gt", "gt", {"simple_0": [True]})
    _run(tmp_path / "b" / "reference_panda_gt", "gt", {"simple_0": [False]})
    runs = find_runs([tmp_path / "a", tmp_path / "b"])
    assert [r.label for r in runs] == [
        "reference · gt · panda (a/reference_panda_gt)",
        "reference · gt · panda (b/reference_panda_gt)",
    ]
    (tmp_path / "empty").mkdir()
    assert main(["report", str(tmp_path / "empty"), "--out", str(tmp_path / "r")]) == 2


def test_the_report_command_prints_the_tables_and_writes_the_page(tmp_path, capsys):
    _run(tmp_path / "run", "gt", {"simple_0": [True, False]})
    assert main(["report", str(tmp_path / "run"), "--out", str(tmp_path / "r")]) == 0
    printed = capsys.readouterr().out
    assert "### Whole task success" in printed and "index.html" in printed
    assert json.loads((tmp_path / "run" / "summary.json").read_text())["tasks"]["simple_0"]["trials"] == 2
