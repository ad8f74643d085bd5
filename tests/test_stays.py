"""Generated tasks check what their words imply stays as it was (roboscript.generate.stays): a program that moves
everything passes no sorting task, while things a query leaves open are checked neither way."""

import pytest

from roboscript.bench.tasks import load_suite
from roboscript.bench.trial import TrialSpec, run_trial
from roboscript.generate.scene import Scene
from roboscript.generate.stays import STAY_WITHIN, stays_out, stays_put, stays_shut
from roboscript.objects.reading import said_colour, said_kind
from roboscript.sim.world_catalog import load_world

SUITE = load_suite("generated")


def _kept_off(task) -> dict[str, set[str]]:
    """For each receptacle, the things a negated in/on check keeps out of it."""
    out: dict[str, set[str]] = {}
    for check in task.checks:
        if check.negate and check.kind in ("in", "on"):
            out.setdefault(check.target, set()).add(check.subject)
    return out


@pytest.mark.parametrize("task_id", [t for t in SUITE if t.startswith("sort_by")])
def test_moving_every_object_passes_no_sorting_task(task_id):
    """Whichever of its receptacles a sloppy program empties the table onto, a thing whose name says another colour
    or kind is checked off it; no thing whose name says no colour or kind is checked either way."""
    task = SUITE[task_id]
    world = load_world(task.world)
    receptacles = {c.target for c in task.checks if not c.negate}
    kept_off = _kept_off(task)
    assert set(kept_off) == receptacles, task.query
    say = said_colour if "by colour" in task.instruction else said_kind
    for names in kept_off.values():
        assert all(say(n) is not None for n in names)
    assert all(o.type.pickable for o in world.objects if o.name in set().union(*kept_off.values()))


def test_each_family_checks_what_its_words_leave_in_place():
    def checks_of(family: str):
        return [t for t in SUITE.values() if t.label == family]

    for task in checks_of("next_to"):
        target = task.checks[0].target
        stays = [c for c in task.checks if c.kind == "at" and c.subject == c.start_of == target]
        assert [c.within for c in stays] == [STAY_WITHIN], task.id
    for task in checks_of("swap"):
        moved = {task.checks[0].subject, task.checks[1].subject}
        stays = {c.subject for c in task.checks[2:]}
        assert stays == set(load_world(task.world).object_names()) - moved
    for task in checks_of("clear_table"):
        world = load_world(task.world)
        assert {c.subject for c in task.checks if c.kind == "at"} == set(Scene(world).receptacles)
    for family in ("into_drawer", "open_door", "close_drawer", "into_cupboard"):
        for task in checks_of(family):
            used = task.checks[0].subject
            shut = {c.subject for c in task.checks if c.kind == "joint" and c.negate and c.subject != used}
            assert used not in shut and shut, task.id


def test_parts_that_start_open_and_things_already_there_are_not_checked():
    task = next(t for t in SUITE.values() if t.label == "close_drawer")
    scene = Scene(load_world(task.world))
    drawer = task.checks[0].subject
    assert drawer not in {c["joint"] for c in stays_shut(scene, [drawer])}
    assert stays_shut(scene, scene.world.part_names()) == ()
    assert stays_put(["apple"]) == ({"at": "apple", "start_of": "apple", "within": STAY_WITHIN},)
    # into_container.gen_025: the green mug starts in the basket and may stay there.
    task = SUITE["into_container.gen_025"]
    scene = Scene(load_world(task.world))
    assert scene.holding("basket") == ["green_mug"] and stays_out(scene, "basket", ["green_mug"]) == ()
    assert [c.describe() for c in task.checks] == [
        "in(medication_bottle, basket)", "not in(orange, basket)", "not in(rubiks_cube, basket)"
    ]  # fmt: skip


def test_a_program_that_also_moves_another_colour_fails_the_sorting_task():
    """sort_by_colour.gen_078 asks for the blue objects on the blue plate; a program that puts the green apple
    there too fails on the apple alone, in the simulator."""
    program = SUITE["sort_by_colour.gen_078"].reference_program() + (
        "\npick('green_apple')\nput('green_apple', parse_place_pose(object_name='green_apple', "
        "receptacle_name='blue_plate'))\n"
    )
    record = run_trial(TrialSpec("sort_by_colour.gen_078", "panda", 0, 0, program=program, suite="generated"))
    results = {c["check"]: c["passed"] for c in record.checks}
    assert results == {"on(blue_cup, blue_plate)": True, "not on(green_apple, blue_plate)": False}, record.error
