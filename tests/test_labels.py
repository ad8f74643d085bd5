"""Labels from descriptions, for robots without ground truth: a world file's furniture (which handle moves which
part, and how) and a segmentation node's label names (their kinds, and objects' categories and colours)."""

from __future__ import annotations

import math

from roboscript.assembly import furniture_labels
from roboscript.perception.detection.labels import segment_labels
from roboscript.sim.world_catalog import load_world


def test_a_world_files_cabinet_becomes_labels_of_its_parts_and_handles():
    labels = furniture_labels(load_world("world_5_mug_to_cabinet"))  # three drawers over a door
    names = labels.furniture()
    assert {"cabinet", "cabinet.drawer_2", "cabinet.door_0", "cabinet.handle_3"} <= set(names)
    (door,) = labels.joints("cabinet.handle_3")
    assert (door.part, door.type) == ("cabinet.door_0", "revolute") and math.isnan(door.value)
    (drawer,) = labels.joints("cabinet.handle_1")
    assert (drawer.part, drawer.type) == ("cabinet.drawer_1", "prismatic")
    assert [j.part for j in labels.joints("cabinet")] == [
        "cabinet.drawer_0",
        "cabinet.drawer_1",
        "cabinet.drawer_2",
        "cabinet.door_0",
    ]
    assert labels.joints("white_and_yellow_mug") == []


def test_segmentation_label_names_get_their_kinds_and_the_librarys_categories():
    labels = segment_labels(
        {0: "table", 1: "white_and_yellow_mug", 2: "cabinet", 3: "cabinet.handle_0", 4: "robot", 5: "apple_2"},
        furniture=["cabinet"],
    )
    by_name = {label.name: label for label in labels}
    assert by_name["table"].kind == "table" and by_name["robot"].kind == "robot"
    assert by_name["cabinet"].kind == "furniture" and by_name["cabinet.handle_0"].kind == "part"
    mug = by_name["white_and_yellow_mug"]
    assert (mug.kind, mug.category) == ("object", "mug") and mug.color
    assert by_name["apple_2"].category == "apple"  # a numbered instance of a library type
