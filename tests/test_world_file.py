import math

import pytest

from roboscript.sim.world_catalog import load_world, world_names
from roboscript.sim.world_file import WorldFileError, load_world_file, parse_world


def write(tmp_path, text, name="bad.yaml"):
    path = tmp_path / name
    path.write_text(text)
    return path


PAPER_WORLDS = [
    "world_1_table_sort",
    "world_2_pick_and_place",
    "world_3_mug_to_empty_plate",
    "world_4_clear_table_to_basket",
    "world_5_mug_to_cabinet",
    "world_6_mug_to_same_color_plate",
]


def test_packaged_worlds_are_the_papers_six_and_their_cluttered_variants():
    assert world_names() == sorted([w.replace("world_", "cluttered_") for w in PAPER_WORLDS] + PAPER_WORLDS)
    for name in world_names():
        world = load_world(name)
        assert world.objects and world.query_names()[0] == "table"
    for name in PAPER_WORLDS:  # every paper world has the cabinet the original's queries list
        assert [c.name for c in load_world(name).cabinets] == ["cabinet"]


def test_the_paper_worlds_hold_the_originals_objects_by_its_names():
    assert load_world("world_1_table_sort").object_names() == [
        "apple",
        "banana",
        "white_ceramic_plate",
        "white_and_pink_box",
        "brown_box",
        "brown_medication_bottle",
        "bleach_cleanser",
        "red_plastic_bowl",
        "mustard_bottle",
    ]
    assert load_world("world_2_pick_and_place").object_names() == ["apple", "footed_bowl"]
    world_3 = load_world("world_3_mug_to_empty_plate")
    lemon = next(o for o in world_3.objects if o.name == "lemon")
    assert lemon.support == "turquoise_salad_plate" and lemon.support_kind == "on"
    assert load_world("world_6_mug_to_same_color_plate").query_names() == [
        "table",
        "cabinet",
        "green_plant_plate",
        "white_ceramic_plate",
        "red_plant_saucer",
        "white_porcelain_mug",
        "cabinet.drawer_0",
        "cabinet.drawer_1",
        "cabinet.drawer_2",
        "cabinet.handle_0",
        "cabinet.handle_1",
        "cabinet.handle_2",
    ]


def test_unknown_object_type_names_file_entry_and_suggestion(tmp_path):
    path = write(
        tmp_path,
        "name: w\nobjects:\n  - {name: a, type: apple, position: [0, 0]}\n"
        "  - {name: fruit, type: aple, position: [0.2, 0.2]}\n",
    )
    with pytest.raises(WorldFileError) as info:
        load_world_file(path)
    message = str(info.value)
    assert str(path) in message
    assert "objects[1] 'fruit'" in message
    assert "unknown object type 'aple'" in message and "apple" in message


def test_missing_field_is_named(tmp_path):
    path = write(tmp_path, "name: w\nobjects:\n  - {name: a, position: [0, 0]}\n")
    with pytest.raises(WorldFileError, match=r"bad.yaml: objects\[0\] 'a': missing required field 'type'"):
        load_world_file(path)


def test_missing_objects_list_is_named(tmp_path):
    with pytest.raises(WorldFileError, match="world: missing required field 'objects'"):
        load_world_file(write(tmp_path, "name: w\n"))


def test_overlapping_objects_are_named(tmp_path):
    path = write(
        tmp_path,
        "name: w\nobjects:\n  - {name: a, type: apple, position: [0, 0]}\n"
        "  - {name: b, type: orange, position: [0.05, 0.0]}\n",
    )
    with pytest.raises(WorldFileError) as info:
        load_world_file(path)
    message = str(info.value)
    assert "objects[1] 'b'" in message and "overlaps objects 'a'" in message and str(path) in message


def test_overlap_with_furniture_and_robot_and_table_edge():
    cabinet = [{"name": "cabinet", "type": "cabinet", "position": [-0.42, 0.62]}]
    with pytest.raises(WorldFileError, match="overlaps furniture 'cabinet'"):
        parse_world(
            {
                "name": "w",
                "furniture": cabinet,
                "objects": [{"name": "a", "type": "apple", "position": [-0.3, 0.6]}],
            }
        )
    with pytest.raises(WorldFileError, match="overlaps the robot base"):
        parse_world({"name": "w", "objects": [{"name": "a", "type": "apple", "position": [-0.45, 0.05]}]})
    with pytest.raises(WorldFileError, match="off the table"):
        parse_world({"name": "w", "objects": [{"name": "a", "type": "apple", "position": [0.64, 0.0]}]})


def test_unknown_field_suggests_the_right_one():
    with pytest.raises(WorldFileError, match=r"unknown field 'postion' \(did you mean 'position'\?\)"):
        parse_world({"name": "w", "objects": [{"name": "a", "type": "apple", "postion": [0, 0]}]})


def test_bad_values_are_explained():
    with pytest.raises(WorldFileError, match="'position' must be a list of 2 numbers"):
        parse_world({"name": "w", "objects": [{"name": "a", "type": "apple", "position": [0, "x"]}]})
    with pytest.raises(WorldFileError, match="unknown robot 'kuka'; valid robots: panda, ur5e"):
        parse_world({"name": "w", "robot": "kuka", "objects": []})
    with pytest.raises(WorldFileError, match="already used"):
        parse_world(
            {
                "name": "w",
                "objects": [
                    {"name": "a", "type": "apple", "position": [0, 0]},
                    {"name": "a", "type": "apple", "position": [0.2, 0.2]},
                ],
            }
        )
    with pytest.raises(WorldFileError, match="must name a drawer; drawers in this world: none"):
        parse_world({"name": "w", "objects": [{"name": "a", "type": "apple", "inside": "cabinet.drawer_0"}]})
    with pytest.raises(WorldFileError, match="row kind must be 'drawer' or 'door'"):
        parse_world(
            {
                "name": "w",
                "objects": [],
                "furniture": [{"name": "c", "type": "cabinet", "position": [-0.42, 0.62], "rows": ["shelf"]}],
            }
        )


def test_yaml_key_on_is_a_string_not_a_boolean(tmp_path):
    path = write(
        tmp_path,
        "name: w\nobjects:\n  - {name: plate, type: white_plate, position: [0, 0]}\n"
        "  - {name: apple, type: apple, on: plate}\n",
        "ok.yaml",
    )
    world = load_world_file(path)
    assert world.objects[1].support == "plate" and world.objects[1].support_kind == "on"


def test_invalid_yaml_is_reported(tmp_path):
    with pytest.raises(WorldFileError, match="is not valid YAML"):
        load_world_file(write(tmp_path, "name: [unclosed\n"))


def test_randomization_is_deterministic_per_seed():
    world = load_world("world_2_pick_and_place")
    a, b, c = world.randomized(3), world.randomized(3), world.randomized(4)
    assert [o.position for o in a.objects] == [o.position for o in b.objects]
    assert [o.position for o in a.objects] != [o.position for o in c.objects]
    for base, moved in zip(world.objects, a.objects, strict=True):
        assert abs(moved.position[0] - base.position[0]) <= world.randomization.position + 1e-12
        assert abs(moved.yaw - base.yaw) <= world.randomization.yaw + 1e-12
    assert world.randomization.yaw == pytest.approx(math.radians(20))
