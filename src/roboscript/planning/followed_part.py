"""A drawer or door that moves with the hand in a planning scene's queries: its joint follows the TCP, turning as
the TCP goes round its hinge, sliding as the TCP goes along its slide."""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from roboscript.geometry import turns_about


@dataclass(frozen=True)
class FollowedPart:
    """The part's joint's qpos address and value at the start, whether it turns, its axis's anchor and direction,
    and where the TCP started."""

    address: int
    start: float
    revolute: bool
    anchor: np.ndarray
    axis: np.ndarray
    tcp_start: np.ndarray

    @classmethod
    def of(cls, model: mujoco.MjModel, data: mujoco.MjData, body: int, tcp: np.ndarray) -> FollowedPart:
        """The part whose body ``body`` carries its joint, as ``data`` has it, with the TCP at ``tcp``."""
        joint = int(model.body_jntadr[body])
        address = int(model.jnt_qposadr[joint])
        revolute = int(model.jnt_type[joint]) == int(mujoco.mjtJoint.mjJNT_HINGE)
        anchor, axis = data.xanchor[joint].copy(), data.xaxis[joint].copy()
        return cls(address, float(data.qpos[address]), revolute, anchor, axis, np.asarray(tcp, dtype=float).copy())

    def value(self, tcp: np.ndarray) -> float:
        """The joint's value with the TCP at ``tcp``: the TCP's turn about the hinge since the start, or its travel
        along the slide."""
        if self.revolute:
            return self.start + float(turns_about(self.axis, self.anchor, self.tcp_start, tcp))
        return self.start + float((tcp - self.tcp_start) @ self.axis)
