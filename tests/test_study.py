"""The object-shape study: its file, its cells written out as a suite of ordinary tasks, one cell run end to end,
and its tables."""

import re

import pytest
import yaml

from roboscript.bench.task_file import load_suite_file
from roboscript.bench.trial import TrialRecord, TrialSpec, run_trial
from roboscript.objects import object_types
from roboscript.study.cells import Cell, select_cells, write_suite
from roboscript.study.study_file import StudyFileError, load_study, parse_study
from roboscript.study.tables import cell_results, failure_kind, object_table, study_csv


def _study_data() -> dict:
    return yaml.safe_load(open(load_study("objects").source))


def test_the_study_covers_every_pickable_type_with_three_grasp_tools():
    study = load_study("objects")
    pickable = [n for n, t in object_types().items() if t.pickable]
    assert list(study.objects) == pickable and len(pickable) >= 40
    assert not {"plate", "bowl", "basket", "saucer"} & {object_types()[n].category for n in pickable}
    assert set(study.grasps) == {"adaptive", "central", "horizontal"}
    assert [t.id for t in study.templates] == ["pick_place", "drawer", "cupboard"]
    assert len(select_cells(study)) == len(pickable) * 3 * 3


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (lambda d: d["templates"][0].update(instruction="pick up the $thing"), "unknown placeholder $thing"),
        (lambda d: d["templates"][0].update(program="detect_objects()\n"), "never uses $grasp"),
        (lambda d: d["templates"][0]["world"].pop("subject"), "missing required field 'subject'"),
        (lambda d: d.update(objects=["apple", "aple"]), "unknown object type 'aple'; did you mean apple"),
        (lambda d: d["grasps"].update(central="parse_central_lift_grasp_pose('$obj')"), "unknown placeholder $obj"),
        (lambda d: d["templates"].append(d["templates"][0]), "template ids must be unique"),
    ],
)
def test_study_file_errors_name_the_entry_and_the_problem(change, message):
    data = _study_data()
    change(data)
    with pytest.raises(StudyFileError, match=re.escape(message)):
        parse_study(data, "study.yaml")


def test_cells_become_a_valid_suite_with_a_world_and_a_program_each(tmp_path):
    study = load_study("objects")
    cells = select_cells(study, ["drawer", "pick_place"], ["banana", "white_mug"], ["horizontal", "central"])
    assert cells[0] == Cell("drawer", "banana", "horizontal") and len(cells) == 8
    with pytest.raises(KeyError, match=r"unknown grasp tool 'suction'.*adaptive, central, horizontal"):
        select_cells(study, grasps=["suction"])
    path = write_suite(study, cells, tmp_path)
    tasks = {t.id: t for t in load_suite_file(path)}
    assert list(tasks) == [c.task_id for c in cells]
    drawer = tasks["drawer.white_mug.central"]
    assert drawer.object_names == ["table", "cabinet", "white_mug", "cabinet.drawer_1", "cabinet.handle_1"]
    assert drawer.instruction == "open the second top drawer and put the white mug into it"
    assert [c.describe() for c in drawer.checks] == ["joint(cabinet.drawer_1) > 0.1", "in(white_mug, cabinet.drawer_1)"]
    program = drawer.reference_program()
    assert "parse_central_lift_grasp_pose(object_name='white_mug', description='center')" in program
    assert "$" not in program and "attach_object('white_mug')" in program
    place = tasks["pick_place.banana.horizontal"]
    assert "parse_horizontal_grasp_pose(object_name='banana')" in place.reference_program()
    assert [c.describe() for c in place.checks] == ["on(banana, basket)"]
    mtime = path.stat().st_mtime_ns
    write_suite(study, cells, tmp_path)  # unchanged files are left as they are
    assert path.stat().st_mtime_ns == mtime


def test_a_cell_runs_as_a_task_and_a_too_wide_object_fails_with_the_reason(tmp_path):
    study = load_study("objects")
    cells = [Cell("pick_place", "golf_ball", "central"), Cell("pick_place", "tuna_can", "central")]
    suite = str(write_suite(study, cells, tmp_path))
    records = []
    for cell in cells:
        program = load_suite_file(suite)[cells.index(cell)].reference_program()
        records.append(run_trial(TrialSpec(cell.task_id, "panda", 0, 3, program, suite=suite)))
    ball, can = records
    assert ball.success, ball.error
    assert not can.success and "wider than the gripper's 8.0 cm opening" in can.error
    assert failure_kind(can) == "GraspError"
    results = cell_results(records, cells)
    assert [(r.object, r.shape, r.successes, r.trials) for r in results] == [
        ("golf_ball", "round", 1, 1),
        ("tuna_can", "cylinder", 0, 1),
    ]
    assert results[1].errors == {"GraspError": 1}


def _record(task: str, trial: int, success: bool, error: str | None = None) -> TrialRecord:
    checks = [{"check": "on(a, basket)", "passed": success, "detail": ""}]
    outcome = "ok" if success else ("planning_failure" if error else "checks_failed")
    return TrialRecord(task, "panda", trial, trial, error is None, error, checks, outcome=outcome)


def test_tables_count_per_object_and_template_with_intervals_and_failure_kinds():
    cells = [Cell("pick_place", "apple", "central"), Cell("drawer", "apple", "central"),
             Cell("pick_place", "cracker_box", "central")]  # fmt: skip
    records = [_record("pick_place.apple.central", i, True) for i in range(10)]
    records += [_record("drawer.apple.central", i, i < 7) for i in range(10)]
    records += [_record("pick_place.cracker_box.central", i, False, "IKError: no solution") for i in range(4)]
    records.append(_record("other_task", 0, True))  # not a cell: ignored
    results = cell_results(records, cells)
    assert [(r.template, r.object, r.successes, r.trials) for r in results] == [
        ("pick_place", "apple", 10, 10), ("drawer", "apple", 7, 10), ("pick_place", "cracker_box", 0, 4)]  # fmt: skip
    assert results[1].errors == {"checks failed: on": 3}
    table = object_table(results, "panda")
    assert "| apple | round | 10/10 | 7/10 |" in table
    assert "| cracker_box | box | 0/4 | - |" in table
    assert "**0.71** [0.45, 0.88]" in table  # pick_place over both objects: 10 of 14, a 95% Wilson interval
    csv = study_csv(results)
    assert "panda,pick_place,cracker_box,central,box,4,0,0.0000,0.0000,0.4899,IKError 4" in csv
