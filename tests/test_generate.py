"""Generation: random worlds, scene descriptions, LLM-suggested tasks, template families with oracle programs, the
generated benchmark and verified data sets."""

from __future__ import annotations

import json
import math
import re
from collections import Counter
from pathlib import Path

import jsonschema
import pytest
import yaml

from chat_server import ScriptedChatServer
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.bench.checks import NEAR_OVERLAP, Check, _footprint_over
from roboscript.bench.task_file import TaskFileError, parse_suite
from roboscript.bench.tasks import load_suite
from roboscript.bench.trial import TrialRecord
from roboscript.cli.main import main
from roboscript.codegen.checker import check_program
from roboscript.generate.dataset import export_records, generate_dataset, schema
from roboscript.generate.describe import describe_scene
from roboscript.generate.families import FAMILIES, FIRST_FAMILIES
from roboscript.generate.preview import settle
from roboscript.generate.recipe import RecipeFileError, load_recipe, parse_recipe
from roboscript.generate.suite import generate_tasks, write_suite
from roboscript.generate.worlds import generate_world
from roboscript.sim.world_file import WorldFileError, parse_world

RECIPE = load_recipe()


def _recipe_data() -> dict:
    return yaml.safe_load(Path(RECIPE.source).read_text())


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"objects": {"count": [3, 2], "types": "pickable"}}, "'count' must be [min, max]"),
        ({"receptacles": {"count": [1, 2], "types": ["white_bowl", "banana"]}}, "'banana' holds nothing"),
        ({"receptacles": {"count": [1, 2], "types": ["white_bowel"]}}, "did you mean white_bowl"),
        ({"region": {"x": [0.2, -0.3], "y": [-0.4, 0.4], "reach": [0.2, 0.7]}}, "low <= high"),
        ({"spacing": 0.5}, "within 0..0.2 m"),
        ({"colour": "red"}, "unknown field 'colour'"),
    ],
)
def test_a_bad_recipe_is_refused_naming_the_entry_and_what_would_be_valid(change, message):
    with pytest.raises(RecipeFileError, match=re.escape(message)):
        parse_recipe({**_recipe_data(), **change}, "recipe.yaml")


def test_a_generated_world_is_valid_and_the_same_for_the_same_seed():
    first, again, other = generate_world(RECIPE, 5, 2), generate_world(RECIPE, 5, 2), generate_world(RECIPE, 5, 3)
    assert first.yaml() == again.yaml()
    assert first.yaml() != other.yaml()
    world = parse_world(yaml.safe_load(first.yaml()), "reloaded")  # the file it writes validates on load
    low, high = RECIPE.object_count
    pickable = [o for o in world.objects if o.type.pickable]
    assert low <= len(pickable) <= high
    assert all(o.type.name in RECIPE.object_types for o in pickable)


def test_generated_worlds_load_and_settle_where_their_files_put_things(tmp_path):
    for index in range(3):
        world = generate_world(RECIPE, 11, index)
        image = tmp_path / f"{index}.png"
        settled = settle(world.spec, image)
        assert settled.ok, settled.moved
        assert settled.lowest > world.spec.table.height - 0.01  # nothing fell off the table
        assert image.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_generate_worlds_writes_world_files_and_top_views(tmp_path):
    assert main(["generate", "worlds", "2", "--seed", "4", "--out", str(tmp_path)]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == [
        "gen_4_000.png",
        "gen_4_000.yaml",
        "gen_4_001.png",
        "gen_4_001.yaml",
    ]


DESCRIBED = {
    "name": "described",
    "furniture": [{"name": "cabinet", "type": "cabinet", "position": [-0.4, 0.6], "width": 0.4,
                   "rows": ["drawer", "drawer"]}],
    "objects": [
        {"name": "white_bowl", "type": "white_bowl", "position": [0.0, -0.25]},
        {"name": "apple", "type": "apple", "on": "white_bowl", "position": [0.0, 0.0]},
        {"name": "blue_plate", "type": "blue_plate", "position": [-0.05, 0.15]},
        {"name": "red_block", "type": "red_block", "position": [-0.2, -0.1]},
    ],
}  # fmt: skip


def test_a_scene_description_says_where_each_thing_is_in_the_checks_terms():
    world = parse_world(DESCRIBED, "described")
    with MujocoBackend(world) as backend:
        text = describe_scene(world, backend.ground_truth)
        backend.sim_world.data.qpos[backend.sim_world.model.joint("cabinet.drawer_1.joint").qposadr[0]] = 0.2
        import mujoco

        mujoco.mj_forward(backend.sim_world.model, backend.sim_world.data)
        opened = describe_scene(world, backend.ground_truth)
    assert "The red apple (apple) is in the white bowl (white_bowl)." in text
    assert "The red block (red_block) is on the table, near the robot." in text
    assert "The blue plate (blue_plate) is empty." in text and "white bowl (white_bowl) is empty" not in text
    assert "Its second drawer (cabinet.drawer_1) is closed." in text
    assert "Its second drawer (cabinet.drawer_1) is open (20 cm)." in opened


def test_near_holds_beside_and_not_on_top_or_far():
    world = parse_world(DESCRIBED, "described")
    with MujocoBackend(world) as backend:
        gt = backend.ground_truth
        assert not Check("near", "red_block", "blue_plate").evaluate(gt).passed  # 13 cm or more apart
        assert not Check("near", "apple", "white_bowl").evaluate(gt).passed  # in it, not beside it
        assert Check("near", "white_bowl", "apple", negate=True).evaluate(gt).passed  # either way round
    tasks = parse_suite(
        {"suite": "s", "tasks": [{"id": "t", "world": "world_2_pick_and_place",
                                  "query": "objects = [apple] ; # x", "checks": [{"near": ["apple", "footed_bowl"]}]}]}
    )  # fmt: skip
    assert tasks[0].checks[0].describe() == "near(apple, footed_bowl)"
    with pytest.raises(TaskFileError, match="objects and furniture"):
        parse_suite(
            {"suite": "s", "tasks": [{"id": "t", "world": "world_2_pick_and_place",
                                      "query": "objects = [apple] ; # x", "checks": [{"near": ["apple", "table"]}]}]}
        )  # fmt: skip


def test_every_family_instantiates_with_checks_that_load_and_programs_that_pass_the_checker(tmp_path):
    tasks = generate_tasks(RECIPE, 30, 0, more=[(load_recipe("cupboard"), 10), (load_recipe("facing_cupboard"), 4)])
    families = Counter(t.task.family.removeprefix("sort_by_").replace("colour", "sort").replace("kind", "sort")
                       for t in tasks)  # fmt: skip
    assert set(families) == set(FAMILIES), families
    suite = write_suite(tasks, tmp_path, "sample", "a test")
    loaded = load_suite(str(suite))
    assert list(loaded) == [t.id for t in tasks]
    for task in loaded.values():
        program = task.reference_program()
        assert check_program(program) == [], (task.id, check_program(program))
        assert program.startswith(f"# Task: {task.instruction}\n# Plan:\n# 1. ")


def test_the_generated_benchmark_is_packaged_and_made_again_by_its_command(tmp_path):
    suite = load_suite("generated")
    worlds = {t.world for t in suite.values()}
    assert len(suite) >= 200 and len(worlds) >= 50
    assert {t.label for t in suite.values()} >= {
        "into_container", "onto_plate", "into_drawer", "stack", "swap", "clear_table", "next_to", "sort_by_colour",
        "open_door", "close_drawer", "into_cupboard",
    }  # fmt: skip
    packaged = Path(next(iter(suite.values())).reference).parent.parent
    description = yaml.safe_load((packaged / "generated.yaml").read_text())["description"]
    command = description.split("`")[1].split()  # the command that made it, as its description says
    assert main([*command[1:], "--out", str(tmp_path)]) == 0
    assert (tmp_path / "generated.yaml").read_text() == (packaged / "generated.yaml").read_text()
    made = sorted(p.relative_to(tmp_path / "generated") for p in (tmp_path / "generated").rglob("*.*"))
    shipped = sorted(p.relative_to(packaged / "generated") for p in (packaged / "generated").rglob("*.*"))
    assert made == shipped  # no file left over from an earlier generation
    for name in made:
        assert (tmp_path / "generated" / name).read_text() == (packaged / "generated" / name).read_text()


SUGGESTIONS = """Here are tasks:
```yaml
- instruction: put the red block on the blue plate
  checks:
    - on: [red_block, blue_plate]
- instruction: put the red block into the green bowl
  checks:
    - in: [red_block, green_bowl]
- instruction: open the second drawer
  checks:
    - {joint: cabinet.drawer_1}
- instruction: leave the apple in the bowl
  checks:
    - on: [apple, white_bowl]
- instruction: put the apple next to the red block
  checks:
    - near: [apple, red_block]
    - on: [apple, table]
- instruction: put the red block on the blue plate
  checks:
    - on: [red_block, blue_plate]
- just a sentence
```"""


def test_suggested_tasks_are_validated_against_the_world_through_a_real_server(tmp_path):
    world_file = tmp_path / "worlds" / "described.yaml"
    world_file.parent.mkdir()
    world_file.write_text(yaml.safe_dump(DESCRIBED))
    out = tmp_path / "suggested.yaml"
    records = tmp_path / "responses"
    with ScriptedChatServer([{"text": SUGGESTIONS}, {"text": "I cannot help with that."}]) as server:
        llm = f"record:{records}=openai:scripted@{server.url}"
        assert main(["generate", "tasks", str(world_file), "--llm", llm, "--count", "6", "--out", str(out)]) == 0
        prompt = server.requests[0]["messages"][-1]["content"]
        assert "The red apple (apple) is in the white bowl (white_bowl)." in prompt
        assert "Names: table, cabinet, white_bowl, apple" in prompt
        bad = tmp_path / "bad.yaml"
        assert main(["generate", "tasks", str(world_file), "--llm", llm, "--out", str(bad)]) == 1
    suite = load_suite(str(out))
    assert [t.instruction for t in suite.values()] == [
        "put the red block on the blue plate",
        "put the apple next to the red block",
    ]
    assert next(iter(suite.values())).world == str(world_file)
    rejected = [json.loads(line) for line in out.with_suffix(".rejected.jsonl").read_text().splitlines()]
    reasons = {r["index"]: r["reason"] for r in rejected}
    assert "'green_bowl' is not one of the world's containers, drawers and doors" in reasons[1]
    assert "'joint' takes above: VALUE" in reasons[2]
    assert reasons[3] == "already done at the start: on(apple, white_bowl)"
    assert reasons[5] == "the same instruction was suggested before"
    assert "a suggestion is a mapping" in reasons[6]
    assert not bad.exists()
    assert "must be a YAML list" in bad.with_suffix(".rejected.jsonl").read_text()
    # Replayed from what was recorded, with no server: the same tasks are kept.
    again = tmp_path / "again.yaml"
    replay = f"replay:{records}=openai:scripted"
    assert main(["generate", "tasks", str(world_file), "--llm", replay, "--count", "6", "--out", str(again)]) == 0
    assert yaml.safe_load(again.read_text())["tasks"] == yaml.safe_load(out.read_text())["tasks"]


def test_a_dataset_keeps_only_verified_programs_in_the_documented_format(tmp_path):
    families = ["onto_plate", "next_to"]
    tasks = generate_tasks(RECIPE, 1, 0, families)
    outcome = generate_dataset(RECIPE, 1, 0, tmp_path, families=families, jobs=2, progress=False)
    assert outcome.trials == len(tasks) == 2 and len(outcome.records) == 2
    lines = (tmp_path / "dataset.jsonl").read_text().splitlines()
    for line in lines:
        record = json.loads(line)
        jsonschema.validate(record, schema())
        assert (tmp_path / record["world"]).is_file()
        assert (
            record["program"] == (tmp_path / "suite" / "dataset" / f"{record['id'].split('.panda')[0]}.py").read_text()
        )
    # A trial that failed a check is not exported.
    failed = TrialRecord(outcome.records[0].id.split(".panda")[0], "panda", 1, 1, True, None,
                         checks=[{"check": "on(x, y)", "passed": False, "detail": "0%"}])  # fmt: skip
    kept = export_records(tmp_path / "suite" / "dataset.yaml", [failed], "reference", tmp_path / "again")
    assert kept == [] and (tmp_path / "again" / "dataset.jsonl").read_text() == ""


def test_a_dataset_from_an_llm_keeps_the_program_it_wrote(tmp_path):
    (task,) = generate_tasks(RECIPE, 1, 0, ["onto_plate"])
    written = task.task.program.replace("# Task:", "# Written by the model. Task:")
    with ScriptedChatServer([{"text": f"```python\n{written}```"}]) as server:
        spec = f"openai:scripted@{server.url}"
        outcome = generate_dataset(RECIPE, 1, 0, tmp_path, policy=f"llm:{spec}", families=["onto_plate"], jobs=1,
                                   progress=False)  # fmt: skip
        assert server.requests[0]["messages"][-1]["content"].endswith(task.query)
    (record,) = outcome.records
    assert record.program_source == spec and record.program.startswith("# Written by the model.")
    jsonschema.validate(json.loads((tmp_path / "dataset.jsonl").read_text()), schema())


def test_families_added_later_leave_the_tasks_of_earlier_worlds_as_they_were():
    """Version 3 added the door and drawer-closing families: the tabletop worlds keep the tasks version 2 gave
    them, and the families that fit no tabletop (no door, no open drawer) never show there."""
    first = [(t.id, t.task) for t in generate_tasks(RECIPE, 20, 0, families=list(FIRST_FAMILIES))]
    now = [(t.id, t.task) for t in generate_tasks(RECIPE, 20, 0)]
    assert now == first


def test_a_world_may_start_with_a_drawer_pulled_out_and_a_door_ajar():
    world = parse_world(
        {
            "name": "ajar",
            "furniture": [
                {"name": "cabinet", "type": "cabinet", "position": [-0.4, 0.6], "width": 0.4,
                 "rows": [{"kind": "drawer", "open": 0.15}, "drawer", {"kind": "door", "open": 30}]}
            ],
            "objects": [],
        }
    )  # fmt: skip
    with MujocoBackend(world, robot="panda", settle=0.3) as backend:
        assert backend.ground_truth.joint("cabinet.drawer_0").value == pytest.approx(0.15, abs=0.005)
        assert backend.ground_truth.joint("cabinet.drawer_1").value == pytest.approx(0.0, abs=0.005)
        assert backend.ground_truth.joint("cabinet.door_0").value == pytest.approx(math.radians(30), abs=0.01)
    with pytest.raises(WorldFileError, match=r"rows\[0\]: row open must be between 0 and 0.25 m"):
        parse_world({"name": "x", "furniture": [{"name": "c", "type": "cabinet", "position": [0, 0.6],
                     "rows": [{"kind": "drawer", "open": 0.5}]}], "objects": []})  # fmt: skip


def test_near_holds_for_turned_things_side_by_side_whose_boxes_overlap_from_above():
    """A tea box turned 150 degrees beside a golf ball: their world-aligned boxes overlap from above by 40%, but
    neither is in or on the other (a program that put the box beside the ball failed this check)."""
    world = parse_world(
        {
            "name": "beside",
            "objects": [
                {"name": "tea_box", "type": "tea_box", "position": [-0.231, 0.193], "yaw": 150.0},
                {"name": "golf_ball", "type": "golf_ball", "position": [-0.175, 0.253]},
            ],
        },
        "beside",
    )
    with MujocoBackend(world, settle=0.3) as backend:
        gt = backend.ground_truth
        result = Check("near", "tea_box", "golf_ball").evaluate(gt)
        assert result.passed, result.detail
        assert _footprint_over(gt.box("golf_ball"), gt.box("tea_box")) > NEAR_OVERLAP  # what the boxes said
