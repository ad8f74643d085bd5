"""The retreats the tools make on a program's behalf: a held object lifted off its support after a grasp, the hand
backed away from what it let go of, before the next motion, unless that motion is itself such a retreat.

As MoveIt's pick and place pipelines do, and as programs written for the original system assume: the original's
GPT-4 programs often neither lift after grasping nor back off after releasing.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.spatial import Delaunay, QhullError

from roboscript.api.held import Held
from roboscript.backends.base import Backend
from roboscript.geometry import Box3D
from roboscript.grasping.detection import GripperGeometry
from roboscript.notices import notice
from roboscript.perception.base import Perception
from roboscript.planning.contacts import ContactAllowances
from roboscript.planning.motion import MotionPlanner

UP = np.array([0.0, 0.0, 1.0])
LIFT_AFTER_GRASP = 0.05
RETREAT_AFTER_RELEASE = 0.05
RELEASE_CLEARANCE = 0.01  # beyond what was let go, where the fingertips end the release retreat if that is further
RELEASE_RETREAT_LEAST = 0.02  # a program's own retreat after a release may stop short of its distance, not of this
OWN_RETREAT = 0.5  # cosine (60 deg) above which a program's motion is its own retreat; wider than PREFERENCE_CONE
FROM_ABOVE = 0.94  # cosine (20 deg) of the approach with straight down above which rising is backing out
LIFT_SIDEWAYS = 0.01  # metres sideways a motion may go and still be a lift (:meth:`Retreats.lift_within_reach`)
LEVEL = 0.5  # sine (30 deg) of a backing-out direction's slope below which the hand backs out level
OUT_FROM_UNDER = 0.4  # metres a hand let go level backs out at most to have nothing over it
OUT_STEP = 0.02
WRIST_LENGTH = 0.08  # metres behind the hand (along the approach) the wrist still counts as the hand
PITCHED_SIDE = 0.71  # sine (45 deg) of an approach's downward slope below which a side grasp backs out level
LEVEL_FINGERS = 0.26  # sine (15 deg) of the closing axis's slope below which the fingers close level


@dataclass(frozen=True)
class Owed:
    """A retreat owed before the next motion: along ``direction`` by ``distance`` metres, after a "lift" (a
    grasp) or a "release"."""

    direction: np.ndarray
    distance: float
    kind: str
    of_object: bool = False  # a release of an object (not of a drawer's or a door's handle)


class Retreats:
    """The retreat owed since the last grasp or release, and how a program's own motions count against it.
    ``leave_where_started`` is called before each motion made (contacts it starts in may be left)."""

    def __init__(
        self,
        motion: MotionPlanner,
        backend: Backend,
        perception: Perception,
        contacts: ContactAllowances,
        held: Held,
        gripper: GripperGeometry,
        leave_where_started: Callable[[], None],
    ):
        self.motion, self.backend, self.perception = motion, backend, perception
        self.contacts, self.held, self.gripper = contacts, held, gripper
        self.leave_where_started = leave_where_started
        self.pending: Owed | None = None
        self.just_made: Owed | None = None  # the retreat the last :meth:`first` made, if it made one

    def owe_lift(self) -> None:
        """After a grasp: off the support, straight up."""
        self.pending = Owed(UP.copy(), LIFT_AFTER_GRASP, "lift")

    def owe_release(self) -> None:
        """After letting go: back along the approach axis (level, for a hand pitched down from the side:
        :func:`_backing_out`), until the fingertips have cleared what was held."""
        back = _backing_out(self.backend.tcp_pose().rotation)
        distance = self._out_from_under(back, self._release_distance(back))
        self.pending = Owed(back, distance, "release", of_object=bool(self.held.objects))

    def first(self, motion: np.ndarray | None, shorter: bool = False) -> Owed | None:
        """Makes the owed retreat, unless ``motion`` (the program's next straight move, as a displacement of the
        TCP; None for a planned one) is already one: mostly along the retreat, and at least as long, or, with
        ``shorter``, after a release, of any length (the caller then makes it as long as the owed one,
        :meth:`own`). Returns the retreat not made when ``motion`` is the program's own retreat, else None."""
        pending, self.pending = self.pending, None
        self.just_made = None
        if pending is None:
            return None
        length = 0.0 if motion is None else float(np.linalg.norm(motion))
        # Away from what was let go is back along the approach, or up where the hand came from above. Fingers
        # that gripped from the side, or tilted, are drawn out first: rising, they dragged a cup let go in a basket
        # or a drawer up with them (a UR5e's open fingers clear a cup's rim by half a millimetre each side).
        # Tilted 39 degrees, the hand rising straight up (within the 60 degrees of any own retreat) hooked a
        # UR5e's fingers under a cup's rim all the same: after letting go of an object from the side or tilted,
        # only a motion within 20 degrees of backing out is the program's own. A handle's bar leaves the fingers
        # any way back: a program's own step back from a high drawer's handle, along the front's normal and not
        # the tilted hand's axis, is its retreat (made first, the owed one left its next pose out of reach).
        from_above = float(pending.direction @ UP) > FROM_ABOVE
        release = pending.kind == "release"
        away = [pending.direction, UP] if release and from_above else [pending.direction]
        cone = FROM_ABOVE if release and pending.of_object and not from_above else OWN_RETREAT
        long_enough = length >= pending.distance or (shorter and release)
        if length > 0.0 and long_enough and any(float(a @ motion) / length > cone for a in away):
            return pending
        self.leave_where_started()
        self.motion.retreat(pending.direction, pending.distance)
        self.contacts.withdraw_cleared(self.held)
        self.just_made = pending
        return None

    def own(self, motion: np.ndarray, owed: Owed) -> bool:
        """The program's own straight retreat from what it just let go of, as far as reach allows: an opened
        drawer's handle, or a place pose in a high drawer, may stand at the edge of the workspace, and the
        retreat's purpose (clearing what was let go) is met before its end. A retreat shorter than the ``owed``
        one is made as long as that: its purpose is the same, and ending a few millimetres past the program's pose
        is nearer to it than making both (a mug let go in a high drawer: the owed 5.7 cm and the program's 5 cm
        up were out of reach together). False where not even :data:`RELEASE_RETREAT_LEAST` is free: the ``owed``
        retreat is then made, and the caller moves as it would have."""
        distance = max(float(np.linalg.norm(motion)), owed.distance)
        moved = self.motion.retreat(motion, distance, least=min(RELEASE_RETREAT_LEAST, distance))
        if moved <= 0.0:
            self.motion.retreat(owed.direction, owed.distance)
            return False
        if moved < distance - 1e-3:
            notice(f"retreat: backed off {moved:.3f} m of {distance:.3f} m: the rest is out of reach")
        self.contacts.withdraw_cleared(self.held)
        return True

    def lift_within_reach(self, rise: np.ndarray) -> bool:
        """A straight lift (up, the hand kept as it is) the arm cannot make in full is made as far as the arm
        reaches, with a notice: a program lifting what it holds clear of a drawer cannot know that 40 cm up is
        beyond reach at the far side of the table. False for any other motion (nothing moved)."""
        if float(np.linalg.norm(rise[:2])) > LIFT_SIDEWAYS or rise[2] <= 0.0:
            return False
        moved = self.motion.retreat(UP, float(rise[2]), least=0.0)
        notice(f"lift: went up {moved:.3f} m of {rise[2]:.3f} m: higher is beyond the arm's reach here")
        self.contacts.withdraw_cleared(self.held)
        return True

    def _out_from_under(self, back: np.ndarray, distance: float) -> float:
        """How far a hand that let go level backs out: ``distance``, or on until nothing the cameras see stands
        over it (a compartment's ceiling), within :data:`OUT_FROM_UNDER`, so that the program's next move up is
        free. Any other hand backs out ``distance``."""
        if abs(float(back[2])) > LEVEL:
            return distance
        tcp = self.backend.tcp_pose()
        lower, upper = np.array(self.gripper.hand_lower), np.array(self.gripper.hand_upper)
        lower[2] -= WRIST_LENGTH
        upper[2] = self.gripper.tip_length
        hand = tcp.apply(Box3D(lower, upper).corners())
        points = self.perception.occupied(list(self.held.objects))
        above = points[(points[:, 2] > hand[:, 2].max() + 0.01) & (points[:, 2] < hand[:, 2].max() + 0.6)]
        if len(above) == 0:
            return distance
        try:
            outline = Delaunay(hand[:, :2])
        except QhullError:
            return distance
        for moved in np.arange(distance, OUT_FROM_UNDER + 1e-9, OUT_STEP):
            if not np.any(outline.find_simplex(above[:, :2] - back[:2] * moved) >= 0):
                return float(moved)
        return distance

    def _release_distance(self, back: np.ndarray) -> float:
        """How far the hand backs out along ``back`` after letting go: :data:`RETREAT_AFTER_RELEASE`, or until the
        fingertips have passed what was let go by :data:`RELEASE_CLEARANCE`. A cup let go from the side reaches
        6 cm back from the TCP: fingertips stopped at its near wall caught its flared rim as the hand rose."""
        tcp = self.backend.tcp_pose().position
        reach = 0.0
        for name in self.held.objects:
            points = self.perception.points(name).points
            if len(points):
                reach = max(reach, float(np.max((points - tcp) @ back)))
        return max(RETREAT_AFTER_RELEASE, reach + self.gripper.tip_length + RELEASE_CLEARANCE)


def _backing_out(rotation: np.ndarray) -> np.ndarray:
    """The direction the hand (turned by ``rotation``; its z axis the approach, its y axis the fingers' closing
    axis) backs out in after letting go: back along the approach, or level where it came from the side pitched
    down with its fingers closing level. Backing out along a pitched approach rises too, and fingers that held a
    cup below its flared rim lift it by the rim and drag it off the plate (a Panda's brown cup, let go at the
    plate's near edge); drawn out level, the fingers slide out in their own plane and leave it standing."""
    approach, closing = rotation[:, 2], rotation[:, 1]
    back = -approach
    pitched_side = 0.0 < -float(approach[2]) < PITCHED_SIDE and abs(float(closing[2])) < LEVEL_FINGERS
    if not pitched_side:
        return back
    level = np.array([back[0], back[1], 0.0])
    return level / float(np.linalg.norm(level))
