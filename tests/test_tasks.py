"""Task suites as data: the paper's queries and checks verbatim, validation of task files, the ``tasks`` command."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.bench.task_file import TaskFileError, parse_query, parse_suite, query_key
from roboscript.bench.tasks import get_task, load_suite, suite_names
from roboscript.sim.world_catalog import load_world

ORIGINAL = Path(__file__).parent / "data" / "original_benchmark"
PAPER_IDS = ["simple_0", "simple_1", "moderate_0", "moderate_1", "moderate_2", "hard_0", "hard_1", "hard_2"]
# The original eval items' functions, as the task files name them.
CHECK_FUNCTIONS = {"check_relation_in": "in", "check_relation_on": "on"}


def _original_items() -> dict[str, dict]:
    """Every original eval item by its query (normalised), with its world."""
    items = {}
    for path in sorted((ORIGINAL / "eval_items").glob("*_eval_items.json")):
        world = path.name.removesuffix("_eval_items.json")
        for item in json.loads(path.read_text()):
            items[query_key(item["query"])] = {**item, "world": world}
    return items


def _described(item: dict) -> list[str]:
    out = []
    for check in item["eval_items"]:
        args = check["args"]
        if check["function"] == "check_object_position":
            start_of = args["position_description"].removeprefix("start_position: ")
            out.append(f"at({args['object_name']}, start of {start_of})")
        else:
            out.append(f"{CHECK_FUNCTIONS[check['function']]}({args['object_name']}, {args['receptacle_name']})")
    return out


def test_the_paper_suite_asks_the_original_queries_character_for_character():
    tasks = load_suite("paper")
    assert list(tasks) == PAPER_IDS
    for task in tasks.values():
        world = Path(task.world).name
        original = (ORIGINAL / "task_queries" / f"{world}.txt").read_text().split("\n")
        assert task.query in original, f"{task.id}: {task.query!r} is not one of {world}'s queries"
    asked = sorted(t.query for t in tasks.values())
    assert asked == sorted(q for p in (ORIGINAL / "task_queries").glob("*.txt") for q in p.read_text().split("\n"))


def test_the_paper_suite_checks_what_the_original_eval_items_check():
    items = _original_items()
    for task in load_suite("paper").values():
        item = items[query_key(task.query)]
        assert item["world"] == task.world
        assert item["query_label"] == task.label
        assert [c.describe() for c in task.checks] == _described(item)


def test_every_query_lists_the_table_first_as_the_originals_do():
    for suite in suite_names():
        for task in load_suite(suite).values():
            assert task.object_names[0] == "table", task.id
            assert load_world(task.world).query_names()[0] == "table"


def test_checks_are_built_from_the_world_as_it_starts():
    task = get_task("hard_1")
    backend = MujocoBackend(task.world, seed=3, randomize=True, settle=0.2)
    apple_at, banana_at = task.build_checks(backend.ground_truth)
    assert apple_at.point == pytest.approx(tuple(backend.ground_truth.box("banana").center))
    assert banana_at.point == pytest.approx(tuple(backend.ground_truth.box("apple").center))
    assert [c.evaluate(backend.ground_truth).passed for c in (apple_at, banana_at)] == [False, False]
    backend.close()


def test_queries_parse_in_both_of_the_originals_forms():
    names, instruction = parse_query("# objects = [table, 'apple', footed_bowl] ; # place it.")
    assert names == ["table", "apple", "footed_bowl"] and instruction == "place it."
    stored, asked = "# objects = ['table', 'apple'] ; # Place  it..", "objects = [table, apple] ; # place it"
    assert query_key(stored) == query_key(asked)
    with pytest.raises(ValueError, match=r"objects = \[table, apple, \.\.\.\] ; # instruction"):
        parse_query("place the apple")


def test_unknown_ids_and_suites_are_named_with_the_valid_ones():
    with pytest.raises(KeyError, match="did you mean simple_0"):
        get_task("simple0")
    with pytest.raises(KeyError, match="unknown suite 'papr'; did you mean paper"):
        load_suite("papr")
    assert get_task("simple_1", "cluttered").checks[0].describe() == "on(brown_cup, blue_plate)"


def _suite(**task) -> dict:
    base = {
        "id": "t",
        "world": "world_2_pick_and_place",
        "query": "objects = [table, apple, footed_bowl] ; # put the apple in the bowl",
        "checks": [{"in": ["apple", "footed_bowl"]}],
    }
    return {"suite": "mine", "tasks": [{**base, **task}]}


@pytest.mark.parametrize(
    ("task", "problem"),
    [
        ({"querry": "x"}, "tasks[0] 't': unknown field 'querry' (did you mean 'query'?)"),
        ({"world": "world_9"}, "world 'world_9': unknown world 'world_9'"),
        ({"query": "put the apple in the bowl"}, "query: a query reads 'objects = [table, apple, ...] ; # instr"),
        ({"query": "objects = [table, aple] ; # go"}, "query lists 'aple', not in world 'world_2_pick_and_place'"),
        ({"checks": []}, "field 'checks' must be a non-empty list"),
        ({"checks": [{"in": ["aple", "footed_bowl"]}]}, "checks[0]: 'aple' is not one of the world's objects; did you"),
        ({"checks": [{"in": ["apple", "table"]}]}, "'table' is not one of the world's containers, drawers and doors"),
        ({"checks": [{"beside": ["apple", "table"]}]}, "a check names exactly one of in, on, near, at, joint"),
        ({"checks": [{"at": "apple"}]}, "'at' takes either start_of: OBJECT"),
        ({"checks": [{"joint": "cabinet.drawer_7", "above": 0.1}]}, "'cabinet.drawer_7' is not one of the world's"),
        ({"checks": [{"on": ["apple", "table"], "not": "yes"}]}, "field 'not' must be true or false"),
        ({"checks": [{"joint": "cabinet.drawer_1"}]}, "'joint' takes above: VALUE"),
        ({"checks": [{"at": "apple", "position": [0, 1]}]}, "field 'position' must be a list of 3 numbers"),
        ({"checks": [{"at": "apple", "start_of": "apple", "within": 0}]}, "'within' is how near in metres, a number"),
        ({"checks": [{"at": "apple", "start_of": "apple", "within": "5 cm"}]}, "field 'within' must be a finite"),
        ({"label": 3}, "field 'label' must be text, got int 3"),
    ],
)
def test_a_bad_task_file_names_the_entry_and_the_problem(task, problem):
    with pytest.raises(TaskFileError) as caught:
        parse_suite(_suite(**task), "mine.yaml")
    assert str(caught.value).startswith("task file mine.yaml: ")
    assert problem in str(caught.value)


def test_a_suite_file_of_ones_own_runs_by_path(tmp_path):
    suite = tmp_path / "mine.yaml"
    suite.write_text(
        "suite: mine\n"
        "tasks:\n"
        "  - id: apple_off_the_table\n"
        "    world: world_2_pick_and_place\n"
        '    query: "objects = [table, apple, footed_bowl] ; # put the apple in the bowl"\n'
        "    checks:\n"
        "      - in: [apple, footed_bowl]\n"
        "      - {on: [apple, table], not: true}\n"
        "      - {joint: cabinet.drawer_0, above: 0.1}\n"
        "      - {at: footed_bowl, start_of: footed_bowl, within: 0.05}\n"
    )
    (task,) = load_suite(str(suite)).values()
    backend = MujocoBackend(task.world, settle=0.2)
    results = [c.evaluate(backend.ground_truth) for c in task.build_checks(backend.ground_truth)]
    backend_bowl = backend.ground_truth.box("footed_bowl").center
    backend.close()
    assert [r.name for r in results] == [
        "in(apple, footed_bowl)",
        "not on(apple, table)",
        "joint(cabinet.drawer_0) > 0.1",
        f"at(footed_bowl, [{', '.join(f'{v:.3f}' for v in backend_bowl)}]) within 0.05 m",
    ]
    # the apple is on the table, the drawer closed, the bowl where it was
    assert [r.passed for r in results] == [False, False, False, True]


def test_the_tasks_command_shows_the_original_queries():
    out = subprocess.run(
        [sys.executable, "-m", "roboscript.cli", "tasks", "--json"], capture_output=True, text=True, timeout=120
    )
    assert out.returncode == 0, out.stderr
    shown = json.loads(out.stdout)
    assert shown["suite"] == "paper"
    assert [t["query"] for t in shown["tasks"]] == [t.query for t in load_suite("paper").values()]
    command = [sys.executable, "-m", "roboscript.cli", "tasks", "--suite", "nope"]
    bad = subprocess.run(command, capture_output=True, text=True, timeout=120)
    assert bad.returncode == 2 and "unknown suite 'nope'" in bad.stderr


def test_every_packaged_task_has_its_reference_program_and_a_variant_may_share_another_suites():
    for suite in suite_names():
        for task in load_suite(suite).values():
            assert task.reference_program().strip(), (suite, task.id)  # raises where the file is missing
    assert load_suite("cluttered")["hard_1"].reference == load_suite("paper")["hard_1"].reference


def test_a_reference_field_must_name_a_program_beside_the_suite_file(tmp_path):
    data = _suite(reference="paper/nothing_here.py")
    with pytest.raises(TaskFileError, match=r"reference: no program at .*nothing_here\.py"):
        parse_suite(data, "mine.yaml", base=tmp_path)
    (tmp_path / "shared.py").write_text("open_gripper()\n")
    task = parse_suite(_suite(reference="shared.py"), "mine.yaml", base=tmp_path)[0]
    assert task.reference_program() == "open_gripper()\n"
