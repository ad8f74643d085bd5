"""Names: what a name stands for."""

import pytest

from roboscript.names import TABLE, is_part, kind_of


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("cabinet.drawer_1", "drawer"),
        ("cabinet.handle_0", "handle"),
        ("wardrobe.door_2", "door"),
        (TABLE, "table"),
        ("cabinet", "other"),
        ("apple", "other"),
        ("drawer_organizer", "other"),  # an object whose name starts like a part is not one
        ("cabinet.shelf_1", "other"),
    ],
)
def test_kind_reads_the_part_from_the_name(name, expected):
    assert kind_of(name) == expected
    assert is_part(name) == (expected in ("drawer", "door", "handle"))
