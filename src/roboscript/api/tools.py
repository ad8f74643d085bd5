"""The tool API: the functions a generated program calls, a thin facade over perception, grasping, placement and
the motion planner of one robot. Every tool checks its arguments first and raises an error that names what was
wrong and what would be valid; a failed tool leaves the world as it was (nothing moves before a motion has been
planned in full). Each doc-string is what the prompt shows an LLM (:mod:`roboscript.codegen.prompt`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from roboscript.api.arguments import ArgumentError, direction, names, one_of, optional, real, vector, whole
from roboscript.api.held import Held, PerceptionFollower, PlanningFollower
from roboscript.api.joints import JOINT_TYPES, joint_report
from roboscript.api.moves import Moves
from roboscript.api.placement import Placer
from roboscript.api.pose import Pose, pose_argument, pose_list
from roboscript.api.program_errors import PROGRAM_ERRORS
from roboscript.api.retreats import Retreats
from roboscript.api.signature import tool
from roboscript.api.spots import DROP
from roboscript.api.supports import stands_in
from roboscript.api.touching import Touching, grasp_family
from roboscript.backends.base import Backend
from roboscript.grasping.choice import GraspChooser
from roboscript.grasping.detection import GraspPreferences, GripperGeometry
from roboscript.perception.base import Perception, UnknownObjectError
from roboscript.phases import timed
from roboscript.planning.cartesian import arc_poses
from roboscript.planning.contacts import ContactAllowances
from roboscript.planning.errors import PlanningError
from roboscript.planning.motion import MotionPlanner

LONGEST_MOVE = 1.5  # metres a move_in_direction may go


class ToolAPI:
    """The tools, bound to one robot. :meth:`namespace` is what a program sees."""

    TOOL_NAMES = (
        "get_object_name_list", "detect_objects", "get_object_center_position", "get_object_pose", "get_3d_bbox",
        "get_object_joint_info", "get_plane_normal", "is_object_in", "parse_central_lift_grasp_pose",
        "parse_horizontal_grasp_pose",
        "parse_adaptive_shape_grasp_pose", "open_gripper", "close_gripper", "get_gripper_pose", "move_to_pose",
        "move_in_direction", "generate_arc_path_around_joint", "follow_path", "grasp", "parse_place_pose",
        "attach_object", "detach_object",
    )  # fmt: skip

    def __init__(self, backend: Backend, perception: Perception, motion: MotionPlanner, seed: int = 0):
        self.backend, self.perception, self.motion, self.seed = backend, perception, motion, seed
        hand = backend.robot.gripper
        self.gripper = GripperGeometry(hand.max_width, hand_lower=hand.hand_box[0], hand_upper=hand.hand_box[1])
        self.base_xy = np.asarray(motion.kinematics.mount.position[:2], dtype=float)
        self.contacts = ContactAllowances(motion, lambda name: grasp_family(perception, name))
        self.held = Held([PlanningFollower(motion, self.contacts), PerceptionFollower(perception)])
        self.touching = Touching(perception, self.contacts, self.held)
        self.placer = Placer(perception, motion, self.base_xy, self.held.taken_from)
        self.grasps = GraspChooser(
            perception, motion, self.contacts, self.gripper, self.base_xy, lambda: self.held, DROP, seed
        )
        self.retreats = Retreats(
            motion, backend, perception, self.contacts, self.held, self.gripper, self.touching.leave_where_started
        )
        self.moves = Moves(
            backend, perception, motion, self.contacts, self.held, self.touching, self.retreats, self.placer
        )

    def namespace(self) -> dict[str, object]:
        """The names a program may use: every tool, ``np``, ``Pose`` and the errors it may catch."""
        return {**{name: getattr(self, name) for name in self.TOOL_NAMES}, "np": np, "Pose": Pose, **PROGRAM_ERRORS}

    # --- perception ------------------------------------------------------------------------------------------

    @tool
    def get_object_name_list(self) -> list[str]:
        """Names of the table, every known object and the furniture with its parts (``cabinet.drawer_0``,
        ``cabinet.handle_0``, ...). A name says what a thing is and, where it has one, its colour (``green_apple``); no
        tool tells colours or kinds otherwise."""
        return list(self.perception.names())

    @tool
    def detect_objects(self, object_list: Sequence[str] | None = None) -> None:
        """Looks with the cameras and updates what is known about these names (all if None); returns None.
        Call it first, and again after something moved that you will measure anew (a drawer you pulled open)."""
        self.perception.detect(optional(names, object_list, "object_list"))
        self.motion.world_changed()

    @tool
    def get_object_center_position(self, object_name: str) -> np.ndarray:
        """Centre of the object's world-aligned 3D box as ``np.array([x, y, z])``, metres, in the world's frame,
        whose axes are the robot's (x forward, y left, z up) but whose origin is not the robot's base."""
        return self.perception.box(self._name(object_name)).center

    @tool
    def get_object_pose(self, object_name: str) -> Pose:
        """The object's Pose: position at the centre of its bottom face (for furniture parts, their body's
        origin), orientation its turn about the vertical."""
        return Pose.from_transform(self.perception.pose(self._name(object_name)))

    @tool
    def get_3d_bbox(self, object_name: str) -> np.ndarray:
        """``np.array([x_min, y_min, z_min, x_max, y_max, z_max])`` of the object's world-aligned box, metres.
        ``get_3d_bbox('table')[5]`` is the height of the table top."""
        return self.perception.box(self._name(object_name)).as_array()

    @tool
    def get_object_joint_info(self, object_name: str, position: Sequence[float], type: str = "any") -> dict:
        """The joint of ``object_name`` (``'cabinet'`` or one of its parts) nearest ``position`` (e.g. a
        handle's centre), of ``type`` ``'any'``, ``'prismatic'`` (drawers) or ``'revolute'`` (doors). Returns a dict:
        ``joint_position`` (a point on the joint's axis), ``joint_axis`` (unit vector), ``type``, ``joint_value``
        (how far it is open now, 0 when shut) and ``joint_upper`` (how far it opens at most); metres for a drawer,
        degrees for a door. A drawer's axis points out of the cabinet: moving the hand along +axis pulls it open,
        along -axis pushes it shut. A door's axis is its hinge, directed so that a positive ``angle`` of
        ``generate_arc_path_around_joint`` opens it."""
        point = vector(position, "position")
        return joint_report(self.perception, self._name(object_name), point, one_of(type, "type", JOINT_TYPES))

    @tool
    def get_plane_normal(self, object_name: str, position: Sequence[float]) -> np.ndarray:
        """Outward unit normal (``np.array``, 3) of the object's flat face nearest ``position``; at a drawer's or
        door's front it points out of the cabinet."""
        return self.perception.plane_normal(self._name(object_name), vector(position, "position"))

    @tool
    def is_object_in(self, object_name: str, receptacle_name: str) -> bool:
        """True when ``object_name`` stands in or on ``receptacle_name`` (a bowl, basket, open drawer or the
        compartment behind a door; a plate, a flat top, ``'table'``), judged in the receptacle's own axes: a thing
        beside a turned basket may lie within its world-aligned box, yet is not in it. False for what is held."""
        name, receptacle = self._name(object_name), self._name(receptacle_name)
        return name != receptacle and name not in self.held and stands_in(self.perception, name, receptacle)

    # --- grasps ----------------------------------------------------------------------------------------------

    @tool
    @timed("grasp")
    def parse_central_lift_grasp_pose(self, object_name: str, description: str = "top") -> Pose:
        """A top-down grasp at the centre of the object's box in x, y, the fingers closing across
        its narrower horizontal side (a long object is gripped across, not along its length). ``description``:
        ``'top'`` (fingertips 3 cm below its top) or ``'center'`` (at mid height, as deep as the fingers reach). The
        object must be narrower across than the gripper opens (8 cm on the Panda, 8.5 cm on the UR5e), else
        GraspError. Where the hand cannot take it from above (a neighbour in the way), the best grasp of its shape,
        with a ``[notice]`` line. Returns the grasp Pose for ``grasp()``."""
        return Pose.from_transform(self.grasps.central(self._name(object_name), description))

    @tool
    @timed("grasp")
    def parse_horizontal_grasp_pose(self, object_name: str, approach_direction: Sequence[float] | None = None) -> Pose:
        """A grasp approaching level (tilted down for a low object): a handle against the front it
        is on, an object from the robot's side across its width (cups and mugs across their body or by their rim).
        ``approach_direction`` (e.g. ``[1, 0, 0]``, away from the robot) is the way the hand moves in: preferred, not
        demanded. Returns the grasp Pose for ``grasp()``; GraspError where no horizontal grasp fits."""
        approach = optional(vector, approach_direction, "approach_direction")
        return Pose.from_transform(self.grasps.horizontal(self._name(object_name), approach))

    @tool
    @timed("grasp")
    def parse_adaptive_shape_grasp_pose(
        self,
        object_name: str,
        preferred_position: Sequence[float] | None = None,
        preferred_approach_direction: Sequence[float] | None = None,
        preferred_plane_normal: Sequence[float] | None = None,
    ) -> Pose:
        """The best reachable grasp of any shape (6-DoF, from the object's observed surface; also
        mugs and bowls wider than the opening, by their rim or handle). Optional preferences: ``preferred_position`` (a
        point to grasp near), ``preferred_approach_direction`` (the way the hand moves in, e.g. ``[0, 0, -1]`` from
        above), ``preferred_plane_normal`` (the fingers close along it). Returns the grasp Pose for ``grasp()``."""
        preferences = GraspPreferences(
            optional(vector, preferred_position, "preferred_position"),
            optional(direction, preferred_approach_direction, "preferred_approach_direction"),
            optional(direction, preferred_plane_normal, "preferred_plane_normal"),
        )
        return Pose.from_transform(self.grasps.adaptive(self._name(object_name), preferences))

    @tool
    def open_gripper(self) -> None:
        """Opens the fingers fully (8 cm apart on the Panda, 8.5 cm on the UR5e), letting go of what they held."""
        self.backend.open_gripper()
        if self.held:  # what was let go stays behind
            self.retreats.owe_release()

    @tool
    def close_gripper(self) -> None:
        """Closes the fingers until they stop on something or close fully. Whether something is held shows at
        ``attach_object``, which raises GraspError where the fingers closed on nothing."""
        self.backend.close_gripper()

    @tool
    def get_gripper_pose(self) -> Pose:
        """The present TCP Pose: position between the fingertips; orientation with z the approach direction
        (out of the hand) and y the direction the fingers close along."""
        return Pose.from_transform(self.backend.tcp_pose())

    @tool
    def move_to_pose(self, pose: Pose) -> None:
        """Moves the TCP to ``pose``, straight where that is free, else along a planned collision-free path,
        carrying what is attached. Raises IKError or PlanningError where it cannot (nothing moved)."""
        self.moves.to_pose(pose_argument(pose, "pose"))

    @tool
    def move_in_direction(self, axis: Sequence[float], distance: float) -> None:
        """Moves the TCP in a straight line along ``axis`` (any non-zero 3-vector, normalised) by ``distance``
        metres (negative: backwards; at most 1.5), keeping its orientation and carrying what is attached; a line
        blocked on the way becomes a planned path to its end. Raises IKError or PlanningError where it cannot."""
        unit, distance = direction(axis, "axis"), real(distance, "distance")
        if abs(distance) > LONGEST_MOVE:
            raise ArgumentError(f"distance must be between -{LONGEST_MOVE} and {LONGEST_MOVE} metres, got {distance}")
        self.moves.in_direction(unit, distance)

    @tool
    def generate_arc_path_around_joint(
        self, current_pose: Pose, joint_axis: Sequence[float], joint_position: Sequence[float], n: int, angle: float
    ) -> list[Pose]:
        """``n`` TCP Poses turning ``current_pose`` about the axis ``joint_axis`` through
        ``joint_position`` by ``angle`` degrees in all (right-handed about the axis), the last at the full angle; for
        ``follow_path``."""
        start, axis = pose_argument(current_pose, "current_pose"), direction(joint_axis, "joint_axis")
        pivot = vector(joint_position, "joint_position")
        n, angle = whole(n, "n", 1, 1000), real(angle, "angle")
        if abs(angle) > 360:
            raise ArgumentError(f"angle is in degrees and must be within [-360, 360], got {angle}")
        return [Pose.from_transform(t) for t in arc_poses(start, axis, pivot, n, math.radians(angle))]

    @tool
    def follow_path(self, path: Sequence[Pose]) -> None:
        """Moves the TCP through the list of Poses, in order, as one Cartesian path, carrying what is attached; a
        door held swings as far along it as the arm reaches (a ``[notice]`` line says how far, if short; where that
        is less than a fifth of the path, nothing moves and CartesianPathIncompleteError says how far it could)."""
        self.moves.along(pose_list(path, "path"))

    @tool
    def grasp(self, grasp_pose: Pose) -> None:
        """Moves to a pre-grasp pose 0.1 m back along the grasp pose's approach (z) axis, then straight to
        ``grasp_pose``.

        The gripper is not closed; call ``close_gripper()`` next."""
        self.moves.grasp(pose_argument(grasp_pose, "grasp_pose"))

    @tool
    @timed("place")
    def parse_place_pose(
        self, object_name: str, receptacle_name: str | None = None, position: Sequence[float] | None = None
    ) -> Pose:
        """A reachable, collision-free gripper Pose that sets the held (attached) ``object_name`` down;
        ``move_to_pose`` there, then ``open_gripper()``. Give ``receptacle_name``, ``position`` or both:

        - ``receptacle_name``: into a container or an open drawer, onto a plate, or on top of any object with a flat
          top (stacking); ``'table'``: aside on a free spot of the table at least 15 cm from where it stood (its
          place stays free for another thing); a door opened 40 degrees or more
          (``'cabinet.door_0'``): into the compartment behind it, carried in level: grasp the object with
          ``parse_horizontal_grasp_pose`` first (after ``open_gripper()`` the hand backs out the way it came).
        - ``position`` ``[x, y, z]``: the object's middle goes above (x, y), resting on whatever is there (the table, or
          an object's top, a bowl or open drawer beneath); z may be anything. With ``receptacle_name`` too: at
          that position, in or on it.
        - Where that spot is taken, out of reach, off its support or within 20 cm of the robot's base (the arm could
          not take it up again), the object goes to the nearest free, reachable spot within 15 cm (a ``[notice]``
          line says where; one nearer the base where there is none); farther away, PlacementError says how far."""
        name = self._name(object_name)
        if receptacle_name is None and position is None:
            raise ArgumentError(
                "give receptacle_name (e.g. 'plate', 'cabinet.drawer_1', 'table'), position [x, y, z], or both"
            )
        self.held.require(name, "parse_place_pose")
        receptacle = None if receptacle_name is None else self._name(receptacle_name)
        target = None if position is None else vector(position, "position")
        return Pose.from_transform(self.placer.place_pose(name, receptacle, target, self.backend.tcp_pose()))

    @tool
    def attach_object(self, object_name: str) -> None:
        """Tells the planner the gripper holds ``object_name`` (an object, or a drawer or door by its handle), after
        ``close_gripper()``. An object is then lifted 5 cm off its support; GraspError if the fingers closed on
        nothing."""
        name = self._name(object_name)
        is_object = name in self.perception.objects()
        if not is_object and "." not in name:
            movable = [n for n in self.perception.furniture() if "." in n]
            raise ArgumentError(
                f"{name!r} cannot be held: it does not move. Attach what the gripper holds: an object "
                f"({', '.join(self.perception.objects()) or 'none'}) or a drawer or door, or its handle "
                f"({', '.join(movable) or 'none'})"
            )
        if name not in self.held:
            self.moves.take(name, is_object, self.gripper.max_width)

    @tool
    def detach_object(self, object_name: str) -> None:
        """Tells the planner ``object_name`` was let go (after ``open_gripper()``). Before the next motion the hand
        backs away from it (up, or back along its approach), unless that motion is itself such a retreat."""
        self.held.let_go(self._name(object_name), self.backend.tcp_pose())

    def _name(self, name: object) -> str:
        return self.perception.require(name)


__all__ = ["PlanningError", "ToolAPI", "UnknownObjectError"]
