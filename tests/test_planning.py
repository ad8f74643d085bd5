"""Planning: IK accuracy, planner validity, Cartesian fractions, held objects, timing limits, typed errors."""

import subprocess
import sys

import numpy as np
import pytest

from helpers import ARMS
from helpers import DOWN_QUAT as DOWN
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.geometry import Transform, rotation_angle_between
from roboscript.planning import (
    CartesianPathIncompleteError,
    IKError,
    MotionPlanner,
    PlannerTimeoutError,
    StateInCollisionError,
    UnknownPlannerError,
    arc_poses,
    cartesian_path,
    ik_solutions,
    planner_names,
    time_parameterize,
)
from roboscript.planning.approaches import approaches
from roboscript.planning.ground_truth_scene import ground_truth_motion
from roboscript.planning.ik import TCP_POSE_COLLIDES, IKSearch
from roboscript.planning.planner import (
    CONSTRAINED_RANGE,
    JointPlanner,
    densify,
    import_ompl,
    pose_distance,
    same_pose,
    whole_turn_equivalents,
    whole_turns,
)
from roboscript.planning.roadmap import roadmap_path
from roboscript.planning.scene_variants import held_clearance
from roboscript.sim.world_file import parse_world

ROBOTS = ARMS
TABLE = 0.82


def planner_for(world, robot, **kwargs) -> tuple[MujocoBackend, MotionPlanner]:
    backend = MujocoBackend(world, robot=robot, settle=0.3)
    return backend, ground_truth_motion(backend, **kwargs)


def objects_world(*objects):
    return parse_world({"name": "planning", "objects": list(objects)})


@pytest.fixture(scope="module", params=ROBOTS)
def table_world(request):
    return planner_for("cluttered_1_table_sort", request.param)


def test_fk_of_ik_is_within_1mm_and_1_degree(table_world):
    backend, motion = table_world
    kinematics = motion.kinematics
    rng = np.random.default_rng(7)
    home = backend.joint_positions()
    for _ in range(15):
        target = kinematics.fk(rng.uniform(kinematics.lower, kinematics.upper))
        q = ik_solutions(kinematics, target, home)[0]
        reached = kinematics.fk(q)
        assert np.linalg.norm(reached.position - target.position) < 1e-3
        assert np.degrees(rotation_angle_between(reached.quaternion, target.quaternion)) < 1.0
        assert np.all(q >= kinematics.lower) and np.all(q <= kinematics.upper)


def test_planned_paths_are_collision_free_under_exact_dense_checking(table_world):
    backend, motion = table_world
    rng = np.random.default_rng(3)
    start = backend.joint_positions()
    exact = JointPlanner(motion.scene, validation_step=0.001)  # 1 mm steps of any point of the arm
    planned = 0
    for _ in range(6):
        p = np.array([rng.uniform(-0.25, 0.15), rng.uniform(-0.4, 0.3), TABLE + rng.uniform(0.1, 0.3)])
        goal = motion.ik(Transform(p, DOWN), start)
        path = motion.planner.plan(start, goal)
        np.testing.assert_allclose(path.start, start)
        assert same_pose(path.goal, goal, 1e-9)  # the goal, or it turned a whole turn about a joint
        exact.validate(path.waypoints)
        assert np.all(np.isfinite(path.waypoints))
        start, planned = path.goal, planned + 1
    assert planned == 6


@pytest.mark.parametrize("robot", ROBOTS)
def test_20cm_cartesian_move_in_free_space_is_achieved(robot):
    backend, motion = planner_for(objects_world(), robot)
    start = backend.joint_positions()
    pose = motion.kinematics.fk(start)
    result = cartesian_path(
        motion.kinematics, motion.scene, start, [Transform(pose.position + np.array([0.0, 0.2, 0.0]), pose.quaternion)]
    )
    assert result.fraction >= 0.99, result.reason
    end = motion.kinematics.fk(result.waypoints[-1])
    np.testing.assert_allclose(end.position, pose.position + np.array([0, 0.2, 0]), atol=1e-3)
    # Every intermediate TCP position lies on the straight line.
    for q in result.waypoints:
        offset = motion.kinematics.fk(q).position - pose.position
        assert abs(offset[0]) < 1e-3 and abs(offset[2]) < 1e-3


@pytest.mark.parametrize("robot", ROBOTS)
def test_blocked_cartesian_move_reports_the_fraction_and_the_obstacle(robot):
    world = objects_world(
        {"name": "tea", "type": "tea_box", "position": [0.0, 0.0], "yaw": 90}
    )  # wider than open fingers
    backend, motion = planner_for(world, robot)
    top = backend.ground_truth.box("tea").upper[2]
    motion.move_to_pose(Transform(np.array([0.0, 0.0, top + 0.15]), DOWN))
    result = motion.cartesian([Transform(np.array([0.0, 0.0, top - 0.05]), DOWN)])
    assert 0.3 < result.fraction < 0.95, result
    assert "tea" in result.reason
    with pytest.raises(CartesianPathIncompleteError, match="tea") as error:
        motion.move_in_direction([0, 0, -1], 0.2)
    assert 0.3 < error.value.fraction < 0.95


@pytest.mark.parametrize("robot", ROBOTS)
def test_a_held_box_makes_the_planner_avoid_what_the_bare_gripper_clears(robot):
    world = objects_world(
        {"name": "held", "type": "cracker_box", "position": [0.1, -0.35]},
        {"name": "wall", "type": "cereal_box", "position": [0.05, 0.0], "yaw": 90},
    )
    backend, motion = planner_for(world, robot)
    scene = motion.scene
    wall_top = backend.ground_truth.box("wall").upper[2]
    height = wall_top + 0.07  # the fingers clear the wall; a box hanging 19 cm below them does not
    qa = motion.ik(Transform(np.array([0.05, -0.25, height]), DOWN))
    qb = motion.ik(Transform(np.array([0.05, 0.25, height]), qa if False else DOWN), qa)
    straight = densify(np.array([qa, qb]), motion.scene.lever_arms, 0.005)
    assert all(scene.is_valid(q) for q in straight), "the bare gripper passes over the wall"

    _hold(backend, motion, "held", qa, below=0.19)  # the box hangs below the fingers
    blocked = [q for q in straight if not scene.is_valid(q)]
    assert blocked, "the held box must hit the wall on the straight path"
    assert ("held", "wall") in scene.collisions(blocked[0])

    path = motion.planner.plan(qa, qb, "RRTConnect", 10.0)  # one run, no retries: time to spare on a busy machine
    motion.planner.validate(path.waypoints)  # with the box attached
    assert len(path.waypoints) > 2, "the path must detour"
    scene.detach("held")


def test_time_parameterisation_follows_the_path_within_limits():
    rng = np.random.default_rng(0)
    waypoints = np.cumsum(rng.uniform(-0.6, 0.6, size=(6, 7)), axis=0)
    vmax, amax = np.full(7, 1.5), np.full(7, 4.0)
    trajectory = time_parameterize(waypoints, vmax, amax, speed_scale=0.5)
    t = np.arange(0, trajectory.duration, 0.001)
    q, qd, _ = trajectory.sample_many(t)
    assert np.max(np.abs(qd)) <= 0.75 * 1.02
    qdd = np.diff(qd, axis=0) / 0.001
    assert np.percentile(np.abs(qdd), 99.5) <= 2.0 * 1.1
    np.testing.assert_allclose(trajectory.positions[0], waypoints[0])
    np.testing.assert_allclose(trajectory.positions[-1], waypoints[-1])
    np.testing.assert_allclose(trajectory.velocities[[0, -1]], 0.0)
    for w in waypoints:  # the trajectory passes through every waypoint
        assert np.min(np.max(np.abs(q - w), axis=1)) < 0.01


def test_arc_poses_turn_about_the_axis():
    start = Transform(np.array([0.3, 0.2, 1.0]), DOWN)
    pivot, axis = np.array([0.3, 0.5, 1.0]), np.array([0.0, 0.0, 1.0])
    poses = arc_poses(start, axis, pivot, 10, np.radians(60))
    radius = np.linalg.norm(start.position - pivot)
    for k, pose in enumerate(poses, 1):
        assert np.linalg.norm(pose.position - pivot) == pytest.approx(radius)
        assert np.degrees(rotation_angle_between(start.quaternion, pose.quaternion)) == pytest.approx(6 * k)
    with pytest.raises(ValueError, match="axis"):
        arc_poses(start, [0, 0, 0], pivot, 5, 1.0)


def test_failures_are_typed_and_explained():
    world = objects_world({"name": "tea", "type": "tea_box", "position": [0.0, 0.0], "yaw": 90})
    backend, motion = planner_for(world, "panda")
    home = backend.joint_positions()
    with pytest.raises(UnknownPlannerError, match="RRTConnect"):
        motion.planner.plan(home, home, planner="Dijkstra")
    with pytest.raises(UnknownPlannerError, match="not available"):
        motion.planner.plan(home, home, planner="SBL")
    with pytest.raises(IKError, match="nearest pose reached") as error:
        motion.ik(Transform(np.array([1.5, 0.0, 1.0]), DOWN))
    assert error.value.position_error > 0.3
    inside = motion.kinematics.solve(Transform(np.array([0.0, 0.0, TABLE + 0.03]), DOWN), home, max_iterations=200).q
    with pytest.raises(StateInCollisionError, match="tea") as collision:
        motion.planner.plan(inside, home)
    assert collision.value.which == "start"
    with pytest.raises(IKError, match=TCP_POSE_COLLIDES) as collision:
        motion.ik(Transform(np.array([0.0, 0.0, TABLE + 0.03]), DOWN))
    assert any("tea" in pair for pair in collision.value.colliding)
    assert motion.scene.collides_wherever_the_tcp_is(inside)
    assert not motion.scene.collides_wherever_the_tcp_is(home)
    side_a = motion.ik(Transform(np.array([0.0, -0.2, TABLE + 0.05]), DOWN))
    side_b = motion.ik(Transform(np.array([0.0, 0.2, TABLE + 0.05]), DOWN), side_a)
    with pytest.raises(PlannerTimeoutError, match="RRTConnect"):
        motion.planner.plan(side_a, side_b, timeout=1e-5)
    with pytest.raises(ValueError, match="7 joint values"):
        motion.planner.plan(home[:3], home)


def test_whole_turns_of_a_joint_are_the_same_pose():
    lower, upper = np.array([-2 * np.pi, -np.pi]), np.array([2 * np.pi, np.pi])
    q = np.array([1.0, 0.5])
    equivalents = whole_turn_equivalents(q, lower, upper)
    np.testing.assert_allclose(equivalents, [[1.0, 0.5], [1.0 - 2 * np.pi, 0.5]])  # joint 2 has one turn of range
    np.testing.assert_allclose(whole_turns(q, equivalents[1]), [-2 * np.pi, 0.0])
    assert same_pose(q, equivalents[1], 1e-9)
    assert pose_distance(q, q + np.array([0.0, 0.3])) == pytest.approx(0.3)


def test_a_goal_walled_off_one_way_round_is_reached_the_other_way():
    """A UR5e's shoulder housing cannot pan past a basket beside its base (pan -0.67 .. -0.46 collides whatever
    the other joints do): a goal across it is reached by panning the other way round, a whole turn from it."""
    world = objects_world({"name": "basket", "type": "basket_with_fabric_liner", "position": [-0.2, 0.28]})
    backend, motion = planner_for(world, "ur5e")
    start = np.array([0.39, -2.21, 2.17, -1.53, -1.57, 1.79])
    goal = np.array([-1.1, -1.5, 2.03, -2.11, -1.57, -0.15])
    upright = np.array([-0.56, -1.57, 0.0, -1.57, -1.57, 0.0])
    assert ("robot/upper_arm_link", "basket") in motion.scene.collisions(upright)
    path = motion.planner.plan(start, goal, timeout=2.0)
    np.testing.assert_allclose(path.goal, goal + np.array([2 * np.pi, 0, 0, 0, 0, 0]))
    JointPlanner(motion.scene, validation_step=0.002).validate(path.waypoints)
    backend.close()


def test_every_listed_planner_solves_a_simple_query():
    backend, motion = planner_for(objects_world(), "panda")
    start = backend.joint_positions()
    goal = motion.ik(Transform(np.array([0.1, 0.25, TABLE + 0.2]), DOWN))
    for name in planner_names():
        path = motion.planner.plan(start, goal, planner=name, timeout=5.0)
        assert path.planner == name
        motion.planner.validate(path.waypoints)
    assert len(planner_names()) >= 12


# A UR5e goal that comes with its whole-turn equivalents: OMPL's own PRM::solve adds all but the first in its second
# thread, which runs the Python validity checker while holding the roadmap's lock; the calling thread, holding the
# GIL, waits for that lock. It hung within these ten plans in every run (and once crashed on the shared scene).
_PRM_PLANS = """
import numpy as np
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.planning.ground_truth_scene import ground_truth_motion
from roboscript.planning.scene_variants import held_clearance
from roboscript.sim.world_file import parse_world

backend = MujocoBackend(parse_world({"name": "empty", "objects": []}), robot="ur5e", settle=0.3)
motion = ground_truth_motion(backend)
start, goal = backend.joint_positions(), np.array([-1.1, -1.5, 2.03, -2.11, -1.57, -0.15])
for name in ("PRM", "PRMstar") * 5:
    path = motion.planner.plan(start, goal, planner=name, timeout=1.0)
    print(name, path.planner, len(path.waypoints) >= 2)
"""


def test_prm_and_prm_star_plan_to_several_goals_without_hanging():
    """In a subprocess, so that a deadlock fails this test at its timeout rather than hanging the suite."""
    try:
        done = subprocess.run([sys.executable, "-c", _PRM_PLANS], capture_output=True, text=True, timeout=60)
    except subprocess.TimeoutExpired:
        pytest.fail("PRM/PRMstar planning hung: no result in 60 s (OMPL's PRM::solve deadlocks on the GIL)")
    assert done.returncode == 0, done.stderr[-3000:]
    assert done.stdout.split("\n")[:-1] == [f"{name} {name} True" for name in ("PRM", "PRMstar") * 5]


def _wall_problem(star: bool):
    """A 2-D roadmap planner (set up) whose states are free outside a wall at |x| < 0.1, y < 0.6 padded by 0.05."""
    ob, og, _ = import_ompl()
    space = ob.RealVectorStateSpace(2)
    bounds = ob.RealVectorBounds(2)
    bounds.setLow(-1.0)
    bounds.setHigh(1.0)
    space.setBounds(bounds)
    setup = og.SimpleSetup(space)
    # The planner checks motions at discrete steps and may clip a corner between two: it sees the wall padded.
    setup.setStateValidityChecker(lambda state: abs(state[0]) >= 0.15 or state[1] >= 0.65)
    info = setup.getSpaceInformation()
    start, goal = space.allocState(), space.allocState()
    start[0], start[1], goal[0], goal[1] = -0.5, -0.5, 0.5, -0.5
    setup.setStartAndGoalStates(start, goal)
    planner = og.PRMstar(info) if star else og.PRM(info)
    setup.setPlanner(planner)
    setup.setup()
    return ob, planner, space, info


@pytest.mark.parametrize(("star", "improve"), [(False, False), (True, False), (True, True)])
def test_the_roadmap_planners_find_a_way_round_a_wall_in_the_calling_thread(star, improve):
    ob, planner, space, info = _wall_problem(star)
    start, goals = np.array([-0.5, -0.5]), [np.array([0.5, -0.5]), np.array([0.5, 0.9])]  # neither in a straight line
    waypoints = roadmap_path(ob, planner, space, info, start, goals, timeout=0.5, star=star, improve=improve)
    assert waypoints is not None
    np.testing.assert_array_equal(waypoints[0], start)
    assert any(np.array_equal(waypoints[-1], goal) for goal in goals)
    dense = densify(waypoints, np.ones(2), 0.001)
    assert np.all((np.abs(dense[:, 0]) >= 0.1) | (dense[:, 1] >= 0.6)), "the path crosses the wall"


def test_the_roadmap_planners_give_up_at_their_timeout_where_the_goal_is_walled_off():
    ob, planner, space, info = _wall_problem(star=False)
    # Closed off above the wall too: only the start's side is reachable.
    info.setStateValidityChecker(lambda state: abs(state[0]) >= 0.15)
    start, goal = np.array([-0.5, -0.5]), np.array([0.5, -0.5])
    assert roadmap_path(ob, planner, space, info, start, [goal], timeout=0.2, star=False, improve=False) is None


def test_time_parameterisation_handles_corners_closer_than_a_piece():
    waypoints = np.array([[0.0, 0.0], [0.5, 0.0], [0.5, 0.005], [1.0, 0.005]])
    trajectory = time_parameterize(waypoints, np.ones(2), np.ones(2))
    assert np.all(np.isfinite(trajectory.times)) and np.all(np.diff(trajectory.times) > 0)
    np.testing.assert_allclose(trajectory.positions[-1], waypoints[-1])


def test_contacts_allowed_at_pickup_are_withdrawn_once_the_object_leaves_them():
    world = objects_world({"name": "box", "type": "blue_box", "position": [0.0, 0.0]})
    backend, motion = planner_for(world, "panda")
    scene = motion.scene
    center = backend.ground_truth.box("box").center
    grasp = motion.ik(Transform(center, DOWN))
    lifted = motion.ik(Transform(center + np.array([0, 0, 0.1]), DOWN), grasp)
    scene.update(backend.sim_world.data.qpos)
    scene.attach("box", grasp)  # resting on the table: box-table contact allowed
    assert scene.is_valid(grasp)
    state = backend.sim_world.data.qpos.copy()
    state[backend.sim_world.robot.qpos] = lifted
    scene.update(state)  # the box (carried along) has left the table
    assert not scene.is_valid(grasp), "back on the table, the box now collides with it"
    assert ("box", "table") in scene.collisions(grasp)


def test_ik_solutions_are_distinct_and_nearest_first(table_world):
    backend, motion = table_world
    home = backend.joint_positions()
    target = Transform(np.array([0.0, -0.3, TABLE + 0.1]), DOWN)
    solutions = ik_solutions(motion.kinematics, target, home, motion.scene, IKSearch(solutions=4))
    assert len(solutions) >= 2
    distances = [float(np.sum((q - home) ** 2)) for q in solutions]
    assert distances == sorted(distances)
    for i, q in enumerate(solutions):
        np.testing.assert_allclose(motion.kinematics.fk(q).position, target.position, atol=1e-3)
        assert all(not np.allclose(q, other, atol=1e-3) for other in solutions[i + 1 :])


@pytest.mark.parametrize("robot", ROBOTS)
def test_straight_approach_ends_on_the_targets_branch_along_a_line(robot):
    """Near the base, a vertical approach passes close to a singularity: the approach must still be a line."""
    _, motion = planner_for(objects_world(), robot)
    target = Transform(np.array([-0.15, -0.1, TABLE + 0.03]), DOWN)
    goal, approach = approaches(motion, target, 0.1, first=True)[0]
    assert approach is not None
    np.testing.assert_allclose(approach[-1], goal)
    start = motion.kinematics.fk(approach[0]).position
    np.testing.assert_allclose(start, target.position + np.array([0, 0, 0.1]), atol=1e-3)
    assert np.max(np.abs(np.diff(approach, axis=0))) <= 0.2
    for q in approach:
        offset = motion.kinematics.fk(q).position - target.position
        assert np.linalg.norm(offset[:2]) < 1e-3, "every waypoint lies on the vertical line"


def _hand_lowered_onto_a_box() -> tuple[MotionPlanner, list[np.ndarray]]:
    """A Panda over a box and its configurations lowering the open hand from 10 cm above the box's middle to 2 cm
    into it, in 2 mm steps (IK alone: the scene would refuse those that touch)."""
    world = objects_world({"name": "box", "type": "blue_box", "position": [0.0, 0.0]})
    backend, motion = planner_for(world, "panda")
    center = backend.ground_truth.box("box").center
    motion.scene.update(backend.sim_world.data.qpos)
    above = motion.ik(Transform(center + np.array([0.0, 0.0, 0.1]), DOWN))
    heights = np.arange(0.1, -0.02, -0.002)
    solve = motion.kinematics.solve
    return motion, [solve(Transform(center + np.array([0.0, 0.0, h]), DOWN), above).q for h in heights]


def test_a_contact_may_be_left_or_brushed_but_not_pushed_into():
    """Fingers round a box they just let go of: the motion may start there and leave, but a configuration that
    sinks the hand deeper into the box stays a collision; forbidding the pair again ends the allowance."""
    motion, configurations = _hand_lowered_onto_a_box()
    scene = motion.scene
    # The first configuration the scene reports (within the padding), and one 1 cm lower.
    first = next(k for k, q in enumerate(configurations) if not scene.is_valid(q))
    touching, deeper, clear = configurations[first], configurations[first + 5], configurations[0]
    assert any(b == "box" for _, b in scene.collisions(touching))
    scene.allow_leaving("gripper", "box", touching)
    assert scene.is_valid(touching) and scene.is_valid(clear)
    assert not scene.is_valid(deeper) and any(b == "box" for _, b in scene.collisions(deeper))
    scene.allow("gripper", "box", False)
    assert not scene.is_valid(touching)


def test_a_path_screen_from_within_a_contact_may_leave_it_as_the_motion_will():
    """A hand that ended within the padding of a box (a held object slipped in the fingers near a link, say):
    ``connects`` screens the way out as the motion itself will be allowed to make it, and allows nothing after."""
    motion, configurations = _hand_lowered_onto_a_box()
    scene = motion.scene
    clear = configurations[0]
    touching = next(q for q in configurations if not scene.is_valid(q))
    with pytest.raises(StateInCollisionError):
        motion.planner.plan(touching, clear, motion.default_planner, 2.0)
    assert motion.connects(touching, clear)
    assert not scene.is_valid(touching), "the screen's allowance ends with it"


def test_a_transfer_lifts_the_held_object_clear_and_carries_it_clear():
    """A box held as it rests on the table goes straight up until it is 2 cm clear of everything, stays so on the
    planned part of the path, and comes straight down into the goal beside a wall."""
    from roboscript.planning.transfer import HELD_CLEARANCE, plan_transfer

    world = objects_world(
        {"name": "box", "type": "blue_box", "position": [0.1, -0.25]},
        {"name": "wall", "type": "cereal_box", "position": [0.1, 0.0], "yaw": 90},
    )
    backend, motion = planner_for(world, "panda")
    scene, kinematics = motion.scene, motion.kinematics
    center = backend.ground_truth.box("box").center
    start = motion.ik(Transform(center, DOWN))
    goal = motion.ik(Transform(center + np.array([0.0, 0.5, 0.0]), DOWN), start)
    state = backend.sim_world.data.qpos.copy()
    state[backend.sim_world.robot.qpos] = start
    scene.update(state)
    scene.attach("box", start)  # resting on the table: the contact is allowed until the box leaves it
    path = plan_transfer(motion.planner, kinematics, start, goal, "RRTConnect", 5.0)
    np.testing.assert_allclose(path.waypoints[0], start)
    np.testing.assert_allclose(path.waypoints[-1], goal, atol=1e-6)
    heights = [kinematics.fk(q).position[2] for q in path.waypoints]
    assert max(heights) > center[2] + HELD_CLEARANCE
    # The planner checks its path every validation step (the padding) of any point's travel: between two checks a
    # point may come closer by up to that step, so the clearance it keeps for certain is HELD_CLEARANCE less it.
    kept = HELD_CLEARANCE - motion.planner.validation_step
    with held_clearance(scene, kept):
        clear = [scene.is_valid(q) for q in densify(path.waypoints, motion.scene.lever_arms, 0.005)]
    # Too close only along the straight lines at either end: where clear, the path stays clear until it descends.
    first, last = clear.index(True), len(clear) - 1 - clear[::-1].index(True)
    assert all(clear[first : last + 1])
    motion.planner.validate(path.waypoints)  # and the whole of it is free with the ordinary padding


@pytest.mark.parametrize("robot", ROBOTS)
def test_a_carry_goes_over_what_its_straight_line_meets_without_a_planner(robot):
    """A box carried level across a wall it would hit goes straight up to the lowest cruise height that clears the
    wall by the held clearance, across, and straight down: no planner run, the whole of it free and upright."""
    from roboscript.planning.path_checks import first_blocked
    from roboscript.planning.transfer import CRUISE_RISES, HELD_CLEARANCE, carry_over, upright

    world = objects_world(
        {"name": "held", "type": "blue_box", "position": [0.1, -0.35]},
        {"name": "wall", "type": "cereal_box", "position": [0.05, 0.0], "yaw": 90},
    )
    backend, motion = planner_for(world, robot)
    scene, kinematics = motion.scene, motion.kinematics
    height = backend.ground_truth.box("wall").upper[2] + 0.04  # the box, 5.5 cm below the TCP, meets the wall
    qa = motion.ik(Transform(np.array([0.05, -0.25, height]), DOWN))
    qb = motion.ik(Transform(np.array([0.05, 0.25, height]), DOWN), qa)
    _hold(backend, motion, "held", qa, below=0.03)
    step = motion.planner.validation_step
    with held_clearance(scene, HELD_CLEARANCE):
        assert first_blocked(scene, np.array([qa, qb]), step) is not None, "the straight carry meets the wall"
    keeps_upright = upright(kinematics, qa, qb)

    waypoints = carry_over(kinematics, scene, qa, qb, keeps_upright, step)

    assert waypoints is not None
    np.testing.assert_allclose(waypoints[0], qa)
    np.testing.assert_allclose(waypoints[-1], qb)
    tcp = np.array([kinematics.fk(q).position for q in waypoints])
    cruise = height + CRUISE_RISES[0]  # 5 cm higher clears the wall by 3.5 cm
    at_start = np.linalg.norm(tcp[:, :2] - tcp[0, :2], axis=1) < 1e-3
    at_goal = np.linalg.norm(tcp[:, :2] - tcp[-1, :2], axis=1) < 1e-3
    # Straight up from the start and straight down to the goal, both to the cruise height (in the lines' 5 mm
    # steps), and across above it.
    assert cruise - 1e-3 <= tcp[at_start, 2].max() < cruise + 5e-3
    assert cruise - 1e-3 <= tcp[at_goal, 2].max() < cruise + 5e-3
    assert np.all(at_start | at_goal | (tcp[:, 2] > cruise - 2e-3))
    dense = densify(waypoints, scene.lever_arms, 0.005)
    assert all(keeps_upright(q) for q in dense)
    motion.planner.validate(waypoints)
    dense_tcp = np.array([kinematics.fk(q).position for q in dense])
    across = dense_tcp[:, 2] > cruise - 2e-3
    with held_clearance(scene, HELD_CLEARANCE - step):  # as a planner's path keeps it: see the transfer test
        assert all(scene.is_valid(q) for q in dense[across])
    backend.close()


def _hold(backend: MujocoBackend, motion: MotionPlanner, name: str, q: np.ndarray, below: float) -> None:
    """Puts object ``name`` in the hand of the arm at ``q``, its centre ``below`` metres under the TCP, and
    attaches it in the planning scene."""
    model, state = backend.sim_world.model, backend.sim_world.data.qpos.copy()
    adr = model.jnt_qposadr[model.body_jntadr[model.body(name).id]]
    state[adr : adr + 3] = motion.kinematics.fk(q).position - [0.0, 0.0, below]
    state[adr + 3 : adr + 7] = [1.0, 0.0, 0.0, 0.0]
    state[backend.sim_world.robot.qpos] = q
    motion.scene.update(state)
    motion.scene.attach(name, q)


def test_a_carried_object_stays_upright_where_the_arm_changes_branch():
    """From one IK branch to another (joints 1 and 3 turned round, as a Panda placing a banana it took with its
    wrist near a limit), a straight joint path tips the hand 48 degrees; under the transfer's path constraint the
    held object tilts no more than its tilt at the goal plus TILT_ALLOWANCE anywhere along the path."""
    import math

    from roboscript.planning.transfer import TILT_ALLOWANCE, UP, held_tilt, upright

    backend, motion = planner_for(objects_world(), "panda")
    kinematics = motion.kinematics
    start = np.array([0.15, -0.2, 1.03, -2.67, -2.83, 3.74, -2.12])
    goal = np.array([-2.85, -0.39, -2.85, -2.49, -0.33, 2.85, 1.36])
    held_up = kinematics.fk(start).rotation.T @ UP

    def tilt(q: np.ndarray) -> float:
        return held_tilt(kinematics, q, held_up)

    limit = tilt(goal) + TILT_ALLOWANCE + math.radians(1)  # the planner checks states 0.08 rad apart
    assert max(tilt(start + (goal - start) * s) for s in np.linspace(0, 1, 50)) > limit  # the straight way tips
    keeps_upright = upright(kinematics, start, goal)
    assert keeps_upright(start) and keeps_upright(goal)
    path = motion.planner.plan(start, goal, "RRTConnect", 10.0, constraint=keeps_upright)
    assert max(tilt(q) for q in densify(path.waypoints, motion.scene.lever_arms, 0.005)) <= limit
    # Under a path constraint the tree grows in short steps (OMPL's default, a fifth of the joint space's extent,
    # rarely meets the constraint all along): the raw path's states lie no farther apart than that.
    raw = motion.planner.plan(start, goal, "RRTConnect", 10.0, simplify=False, constraint=keeps_upright)
    steps = np.linalg.norm(np.diff(raw.waypoints, axis=0), axis=1)
    assert len(raw.waypoints) > 2 and steps.max() <= CONSTRAINED_RANGE + 1e-9
    backend.close()


def test_a_planner_that_runs_out_of_time_retries_with_twice_the_time_and_the_next_goal(monkeypatch):
    """MotionPlanner.plan's retry schedule, with a test double for the OMPL planner that times out twice (the
    machine's load taken as none, then as twice the CPUs)."""
    from roboscript.planning import motion as motion_module
    from roboscript.planning.motion import PLANNING_ATTEMPTS
    from roboscript.planning.planner import JointPath

    monkeypatch.setattr(motion_module, "load_factor", lambda: 1.0)
    backend, motion = planner_for(objects_world(), "panda")
    start = backend.joint_positions()
    goals = [start + 0.1, start + 0.2]
    calls: list[tuple[float, float]] = []

    class TimesOutTwice:
        def plan(self, start, goal, planner, timeout, constraint=None):
            calls.append((float(goal[0] - start[0]), timeout))
            if len(calls) < 3:
                raise PlannerTimeoutError(planner, timeout)
            return JointPath(np.array([start, goal]), planner)

    motion._planner = TimesOutTwice()  # the scene is up to date: nothing replaces it
    path = motion.plan(start, goals, timeout=0.5)
    assert path.attempts == 3 == PLANNING_ATTEMPTS
    assert calls == [(pytest.approx(0.1), 0.5), (pytest.approx(0.2), 1.0), (pytest.approx(0.1), 2.0)]

    class AlwaysTimesOut:
        def plan(self, start, goal, planner, timeout, constraint=None):
            calls.append((float(goal[0] - start[0]), timeout))
            raise PlannerTimeoutError(planner, timeout)

    calls.clear()
    motion._planner = AlwaysTimesOut()
    with pytest.raises(PlannerTimeoutError, match=r"within 2\.00 s"):
        motion.plan(start, goals, timeout=0.5)
    assert [limit for _, limit in calls] == [0.5, 1.0, 2.0]

    calls.clear()
    monkeypatch.setattr(motion_module, "load_factor", lambda: 2.0)  # a busy machine: every run twice as long
    with pytest.raises(PlannerTimeoutError):
        motion.plan(start, goals, timeout=0.5)
    assert [limit for _, limit in calls] == [1.0, 2.0, 4.0]
    assert not motion.connects(start, goals[0], timeout=0.5) and calls[-1][1] == 1.0
    backend.close()


def test_a_path_that_fails_the_dense_validation_is_planned_again_and_screens_the_goal_out():
    """A planner run whose paths all graze something between the planner's coarse checks (a narrow passage)
    is retried like one that ran out of time; to ``connects``, a screen of goals, such a goal does not connect.
    A test double stands in for the OMPL planner."""
    from roboscript.planning.errors import PathInCollisionError
    from roboscript.planning.planner import JointPath

    backend, motion = planner_for(objects_world(), "panda")
    start = backend.joint_positions()
    calls: list[float] = []

    class GrazesOnce:
        def plan(self, start, goal, planner, timeout, constraint=None):
            calls.append(timeout)
            if len(calls) < 2:
                raise PathInCollisionError(942, 1049, [("mug", "cabinet.drawer_1")])
            return JointPath(np.array([start, goal]), planner)

    motion._planner = GrazesOnce()
    assert motion.plan(start, [start + 0.1], timeout=0.5).attempts == 2
    calls.clear()
    assert not motion.connects(start, start + 0.1, timeout=0.5)
    assert motion.connects(start, start + 0.1, timeout=0.5)
    backend.close()


def test_ik_tries_the_given_seeds_before_random_ones(table_world):
    """A configuration chosen for a pose nearby seeds the IK: with one attempt allowed, the only solutions found
    are those the reference and the seed lead to. An arm with a closed form needs no seeds: one attempt finds
    every branch."""
    backend, motion = table_world
    home = backend.joint_positions()
    target = Transform(np.array([0.0, -0.3, TABLE + 0.1]), DOWN)
    branches = ik_solutions(motion.kinematics, target, home, motion.scene, IKSearch(solutions=4))
    far = branches[-1]  # the branch farthest from home: not the one IK from home converges to
    alone = ik_solutions(motion.kinematics, target, home, motion.scene, IKSearch(1, 1, 4))
    if motion.kinematics.closed_form is not None:
        assert len(alone) == len(branches) == 4
        assert all(np.allclose(a, b) for a, b in zip(alone, branches, strict=True))
        return
    assert not any(np.allclose(q, far, atol=1e-2) for q in alone)
    seeded = ik_solutions(
        motion.kinematics, target, home, motion.scene, IKSearch(1, 1, 4), seeds=[far]
    )
    assert any(np.allclose(q, far, atol=1e-2) for q in seeded)


class BoxedBackend(MujocoBackend):
    """Test double: the simulation with the safety box a real arm's backend refuses motions out of."""

    CEILING = TABLE + 0.95

    def workspace_box(self):
        return np.array([-1.3, -1.0, 0.8]), np.array([0.75, 1.0, self.CEILING])


def test_plans_keep_every_link_inside_the_backends_workspace_box():
    """A real arm's backend refuses trajectories that take a link out of its workspace box, so the planner keeps
    inside it: an arm raised straight up is no valid configuration, and paths across the table stay below the
    ceiling (a UR5e planned over the top would be refused by the robot, and the program fail)."""
    backend = BoxedBackend(objects_world(), robot="ur5e", settle=0.3)
    motion = ground_truth_motion(backend)
    scene = motion.scene
    upright = backend.joint_positions().copy()
    upright[1:4] = [-np.pi / 2, 0.0, -np.pi / 2]  # shoulder, elbow and wrist in a line pointing up
    assert not scene.is_valid(upright)
    assert any(pair[1] == "workspace box" for pair in scene.collisions(upright))
    start = backend.joint_positions()
    robot_bodies = sorted(scene.robot.body_ids)
    for x, y in ((0.1, 0.4), (0.1, -0.4), (-0.2, 0.5)):
        goal = motion.ik(Transform(np.array([x, y, TABLE + 0.15]), DOWN), start)
        path = motion.planner.plan(start, goal)
        for q in densify(path.waypoints, scene.lever_arms, 0.005):
            scene.is_free(q)  # places the arm at q
            assert scene.data.xpos[robot_bodies, 2].max() < BoxedBackend.CEILING
        start = goal


def _hand_over_table_at(motion, gap: float, x: float = 0.05, y: float = -0.25) -> tuple[np.ndarray, float]:
    """A configuration with the hand pointing straight down, lowered until its nearest colliding geom is ``gap``
    metres above the table (bisected on the TCP's height); returns it and the gap found."""
    import mujoco

    from roboscript.robots.mujoco_model import is_descendant

    scene, kinematics = motion.scene, motion.kinematics
    model, data = scene.model, scene.data
    tcp_body = model.site_bodyid[scene.robot.tcp_site]
    colliding = (model.geom_contype | model.geom_conaffinity) > 0
    hand = [g for g in range(model.ngeom) if colliding[g] and is_descendant(model, model.geom_bodyid[g], tcp_body)]
    table = [g for g in range(model.ngeom) if colliding[g] and scene.body_labels[model.geom_bodyid[g]] == "table"]
    fromto = np.zeros(6)

    def nearest(q: np.ndarray) -> float:
        scene.place(q)
        return min(mujoco.mj_geomDistance(model, data, a, b, 0.2, fromto) for a in hand for b in table)

    q = motion.ik(Transform(np.array([x, y, TABLE + 0.2]), DOWN))
    low, high = TABLE - 0.05, TABLE + 0.2
    for _ in range(30):
        z = (low + high) / 2
        q = kinematics.solve(Transform(np.array([x, y, z]), DOWN), q).q
        if nearest(q) > gap:
            high = z
        else:
            low = z
    return q, nearest(q)


@pytest.mark.parametrize("robot", ROBOTS)
def test_the_padding_holds_between_bodies_of_several_geoms(robot):
    """Inside the 5 mm padding above the table the hand collides; outside it, it is free. MuJoCo prunes pairs of
    bodies of several geoms each (the table and a finger or a coupler) by body margins, which the scene keeps at
    their geoms' largest: with the compiled ones (zero) a UR5e coupler 2.7 mm above the table passed as free."""
    _, motion = planner_for(objects_world(), robot)
    for gap, free in ((0.0015, False), (0.0025, False), (0.004, False), (0.0065, True)):
        q, found = _hand_over_table_at(motion, gap)
        assert abs(found - gap) < 2e-4, (gap, found)
        assert motion.scene.is_free(q) is free, (gap, motion.scene.collisions(q))


def test_a_way_in_with_no_clear_line_starts_as_far_back_as_the_arm_reaches():
    # A handle at the edge of reach, taken with the hand pointing back at the robot: its pre-grasp lies farther
    # out. A door's handle swung 60 degrees towards a Panda could not be taken from 10 cm back nor from 5.
    from roboscript.errors import RoboScriptError
    from roboscript.planning.approaches import _approach_start

    backend, motion = planner_for("cluttered_1_table_sort", "panda")
    try:
        base = backend.base_pose().position
        inward = Transform.from_rotation(np.zeros(3), np.array([[0, 0, -1.0], [0, 1.0, 0], [1.0, 0, 0]])).quaternion
        reference = backend.joint_positions()

        def reachable(x: float) -> np.ndarray | None:
            try:
                return motion.ik(Transform(base + np.array([x, 0.0, 0.35]), inward), reference)
            except RoboScriptError:
                return None

        # The farthest target from which the hand still reaches 2.5 cm farther out, but not 5 cm.
        edge = [x for x in np.arange(0.3, 1.0, 0.005) if reachable(x) is not None and reachable(x + 0.025) is not None]
        x = max(edge)
        assert reachable(x + 0.05) is None
        target = Transform(base + np.array([x, 0.0, 0.35]), inward)
        start = _approach_start(motion, target, 0.1, reachable(x))
        backed = motion.kinematics.fk(start).position - target.position
        assert np.allclose(backed, [0.025, 0.0, 0.0], atol=2e-3)  # a quarter of the way back: the most in reach
    finally:
        backend.close()
