"""The motions the tools make for a program: each one preceded by the retreat it owes, with the contacts it may
make allowed and withdrawn once clear, and taking hold of what the fingers closed on.

A program's own motion may be the retreat itself (it lifts after a grasp, backs off after a release); a lift or a
retreat beyond the arm's reach is made as far as it goes, with a notice, where failing would serve no purpose.
"""

from __future__ import annotations

import numpy as np

from roboscript.api.held import Held
from roboscript.api.placement import Placer
from roboscript.api.retreats import RETREAT_AFTER_RELEASE, Retreats
from roboscript.api.touching import Touching
from roboscript.backends.base import Backend
from roboscript.geometry import Transform, rotation_angle_between
from roboscript.grasping.choice import PRE_GRASP_DISTANCE
from roboscript.grasping.heuristics import GraspError
from roboscript.names import kind_of
from roboscript.notices import notice
from roboscript.perception.base import Perception
from roboscript.planning.approaches import approaches, finish_approach, move_to_approach
from roboscript.planning.contacts import ContactAllowances
from roboscript.planning.errors import CartesianPathIncompleteError, IKError, PlanningError, TrackingError
from roboscript.planning.motion import MotionPlanner

EMPTY_GRIP = 0.002  # metres: fingers closed this far hold nothing
SAME_ORIENTATION = 0.05  # radians: a move_to_pose turning the hand less is a straight move, a retreat if it backs off
HOLDING = 0.005  # metres: fingers this much short of fully open hold something
PULL_LEAST = 0.005  # metres a drawer or door held must move for a pull to count as made
SWING_LEAST = 0.2  # of a path followed holding a door, the share the arm must reach for it to be made in part


class Moves:
    """Motions of one arm on a program's behalf (see the module's doc-string)."""

    def __init__(
        self,
        backend: Backend,
        perception: Perception,
        motion: MotionPlanner,
        contacts: ContactAllowances,
        held: Held,
        touching: Touching,
        retreats: Retreats,
        placer: Placer,
    ):
        self.backend, self.perception, self.motion, self.contacts = backend, perception, motion, contacts
        self.held, self.touching, self.retreats, self.placer = held, touching, retreats, placer

    def to_pose(self, target: Transform) -> None:
        current = self.backend.tcp_pose()
        motion = target.position - current.position
        own = self.retreats.first(motion, shorter=True)
        self.touching.leave_where_started()
        straight = rotation_angle_between(current.quaternion, target.quaternion) < SAME_ORIENTATION
        retreating = own is not None and own.kind == "release" and straight
        if retreating and self.retreats.own(motion, own):
            return
        self.touching.allow_near(target.position)
        try:
            self.motion.move_to_pose(target)
        except IKError as exc:
            higher = self.placer.raised_for_release(target, exc, self.held)
            if higher is None and straight and self.retreats.lift_within_reach(motion):
                return
            if higher is None and retreating:
                # Backing off from what was let go at the edge of reach (a drawer pulled far out): the fingers
                # are open, and the next motion leaves from here.
                notice("move_to_pose: the retreat from what was let go is beyond the arm's reach: stopped here")
                return
            if higher is None:
                raise
            notice(
                f"move_to_pose: {', '.join(self.held)} sits lower in the hand than when the pose was made: going "
                f"{higher.position[2] - target.position[2]:.3f} m higher"
            )
            self.motion.move_to_pose(higher)
        self.contacts.withdraw_cleared(self.held)

    def in_direction(self, unit: np.ndarray, distance: float) -> None:
        own = self.retreats.first(unit * distance, shorter=True)
        self.touching.leave_where_started()
        retreating = own is not None and own.kind == "release"
        if retreating and self.retreats.own(unit * distance, own):
            return
        parts = [name for name in self.held.names if name not in self.held.objects]
        if parts:
            self._pull(parts, unit, distance)
            return
        try:
            self.motion.move_in_direction(unit, distance, plan_if_blocked=True)
        except IKError:
            if retreating:
                # Backing off a door's handle swung to the edge of reach: the fingers are open, and the next
                # motion leaves from here (as move_to_pose's retreat does).
                notice("move_in_direction: the retreat from what was let go is beyond the arm's reach: stopped here")
                return
            if self._backing_further(unit * distance):
                return
            if not self.retreats.lift_within_reach(unit * distance):
                raise
        self.contacts.withdraw_cleared(self.held)

    def _backing_further(self, motion: np.ndarray) -> bool:
        """A program's step back from what it let go, made after the owed retreat (along another line: a hand
        tilted in a compartment backs out level, the program along its tilted axis), that cannot be made in full
        (the swung door beside it, the edge of reach) is made as far as it is free, with a notice: the hand has
        already left what it let go, which is what the step was for. False for any other motion (nothing moved)."""
        made = self.retreats.just_made
        length = float(np.linalg.norm(motion))
        if made is None or made.kind != "release" or length == 0.0 or float(made.direction @ motion) <= 0.0:
            return False
        moved = self.motion.retreat(motion, length, least=0.0)
        notice(
            f"move_in_direction: backed off {moved:.3f} m of {length:.3f} m from what was let go: the rest is "
            "blocked or beyond the arm's reach"
        )
        self.contacts.withdraw_cleared(self.held)
        return True

    def _pull(self, parts: list[str], unit: np.ndarray, distance: float) -> None:
        """A drawer or door held moves the hand only along its joint: a straight line as far as the arm can
        follow it, never a planned way round (a path that leaves the line drags the hand against the joint), with
        a notice where that is short of ``distance`` (a drawer pulled 24 cm at the edge of the UR5e's reach)."""
        length = abs(distance)
        direction, least = unit * np.sign(distance), min(PULL_LEAST, length)
        start = self.motion.backend.tcp_pose().position
        try:
            moved = self.motion.retreat(direction, length, least=least)
        except TrackingError:
            # The part stopped before the hand: a drawer at the end of its slide, which perception only guesses
            # (a program pulling to the travel it was told, 2 cm past the stop). It stays where it stopped.
            self.motion.hold_here()
            moved = float((self.motion.backend.tcp_pose().position - start) @ direction)
            if moved < least:
                raise
            notice(
                f"move_in_direction: moved {moved:.3f} m of {length:.3f} m holding {', '.join(parts)}: it stopped "
                "there, at the end of its travel or against something"
            )
            self.contacts.withdraw_cleared(self.held)
            return
        if moved <= 0.0:
            raise PlanningError(
                f"move_in_direction: holding {', '.join(parts)}, the hand cannot move even {PULL_LEAST * 100:.0f} cm "
                f"along {np.round(unit * np.sign(distance), 3).tolist()}: the arm's reach or a collision stops it"
            )
        if moved < length - 1e-3:
            notice(
                f"move_in_direction: moved {moved:.3f} m of {length:.3f} m holding {', '.join(parts)}: the rest is "
                "beyond the arm's reach"
            )
        self.contacts.withdraw_cleared(self.held)

    def along(self, targets: list[Transform]) -> None:
        """Follows the path; holding a door, as far along it as the arm reaches, with a notice where that is short
        of its end (a door swung 90 degrees by a hand that reaches 75), the door swept with the hand."""
        self.retreats.first(targets[0].position - self.backend.tcp_pose().position)
        self.touching.leave_where_started()
        doors = [n for n in self.held.names if n not in self.held.objects and kind_of(n) == "door"]
        if doors:
            # A door held swings with the hand along the path: the arm must stay clear of where it sweeps.
            with self.contacts.part_moving(doors[0], self.motion.sync(), held=True):
                line = self.motion.cartesian(targets)
                if line.fraction < SWING_LEAST:
                    raise CartesianPathIncompleteError(line.fraction, line.reason)
                waypoints, fraction = line.waypoints, line.fraction
                if fraction < 1.0:
                    waypoints, fraction = self._where_it_can_let_go(line.waypoints, line.fraction)
                self.motion.execute(waypoints)
            if fraction < line.fraction:
                notice(
                    f"follow_path: holding {doors[0]}, the hand followed {fraction:.0%} of the path and stopped where "
                    f"it can still back off the handle: beyond {line.fraction:.0%} the path is out of the arm's reach "
                    f"({line.reason})"
                )
            elif line.fraction < 1.0:
                notice(
                    f"follow_path: holding {doors[0]}, the hand followed {line.fraction:.0%} of the path: the rest is "
                    f"beyond the arm's reach ({line.reason})"
                )
        else:
            self.motion.follow(targets)
        self.contacts.withdraw_cleared(self.held)

    def _where_it_can_let_go(self, waypoints: np.ndarray, fraction: float) -> tuple[np.ndarray, float]:
        """The waypoints of a door's swing cut short by the arm's reach, up to the last one the hand can back off
        the handle from (:data:`RETREAT_AFTER_RELEASE` along its approach axis, within reach), with the fraction
        of the path that is; all of them where none can (the swing is then as far as the arm goes). At the very
        edge of reach the open fingers stay round the handle: the next motion drags them through it, and a look
        from there cannot see the handle behind the hand."""
        poses = [self.motion.kinematics.fk(q) for q in waypoints]
        steps = np.linalg.norm(np.diff([pose.position for pose in poses], axis=0), axis=1)
        swept = np.concatenate([[0.0], np.cumsum(steps)])
        least = SWING_LEAST / fraction * swept[-1]  # the share of the path a swing must keep
        for index in range(len(waypoints) - 1, 0, -1):
            if swept[index] < least:
                break
            back = -poses[index].rotation[:, 2]
            if self.motion.reach_along(waypoints[index], back, RETREAT_AFTER_RELEASE) >= RETREAT_AFTER_RELEASE - 1e-3:
                return waypoints[: index + 1], fraction * swept[index] / max(swept[-1], 1e-9)
        return waypoints, fraction

    def grasp(self, target: Transform) -> None:
        # The way to the pre-grasp is planned, not straight: it is never the retreat itself, whatever its direction.
        self.retreats.first(None)
        self.touching.leave_where_started()
        # The fingers may touch the object only on the final straight approach, not on the way to its start.
        with self.contacts.touching(self.touching.new_near(target.position)):
            options = approaches(self.motion, target, PRE_GRASP_DISTANCE)
        chosen = move_to_approach(self.motion, options, target, PRE_GRASP_DISTANCE)
        self.touching.allow_near(target.position)
        finish_approach(self.motion, chosen, target)
        self.contacts.withdraw_cleared(self.held)

    def take(self, name: str, is_object: bool, max_width: float) -> None:
        """Takes hold of ``name``; an object is lifted off whatever it rests on at once if the fingers hold it:
        where it settles in the hand, and so what a place pose asked for next must allow for, shows only once it
        hangs free. GraspError where the fingers closed on nothing."""
        self.held.take(name, is_object, self.backend.tcp_pose())
        if not is_object:
            return
        self.retreats.owe_lift()
        if self.backend.gripper_width() >= max_width - HOLDING:
            return
        self.retreats.first(None)
        if self.backend.gripper_width() < EMPTY_GRIP:
            self.held.let_go(name, self.backend.tcp_pose())
            raise GraspError(
                f"{name!r} is not between the fingers: they closed on nothing as the hand lifted it (the grasp "
                "missed, or it slipped out). Open the gripper and grasp it again: nearer its middle, or from above "
                "(preferred_approach_direction=[0, 0, -1])"
            )
        if self.perception.hangs_free(name):
            self.motion.world_changed()  # the planning scene carries it as it hangs
