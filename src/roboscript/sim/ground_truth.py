"""Ground-truth queries on a simulated world: poses, 3D boxes, articulation, contacts.

These answer from the simulator's state, never from perception; the benchmark's checks and the ground-truth mode
of the tool API use them. Boxes are world-axis-aligned and fitted to the geoms' own bounding boxes.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from roboscript.errors import InvalidArgumentError
from roboscript.geometry import Box3D, Transform
from roboscript.sim.furniture import compartment_interior
from roboscript.sim.world import Entity, SimWorld

_CORNER_SIGNS = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], dtype=float)


@dataclass(frozen=True)
class JointInfo:
    """A furniture joint in world coordinates: ``position`` is a point on the axis (the hinge line for doors)."""

    name: str
    type: str  # "prismatic" or "revolute"
    position: np.ndarray
    axis: np.ndarray
    value: float  # metres or radians from closed
    lower: float
    upper: float


@dataclass(frozen=True)
class Contact:
    """A contact between two entities (or unnamed geoms, reported by geom name)."""

    a: str
    b: str
    position: np.ndarray
    normal: np.ndarray  # from a to b
    normal_force: float


def geoms_box(model: mujoco.MjModel, data: mujoco.MjData, geoms: np.ndarray, frame: Transform | None = None) -> Box3D:
    """Axis-aligned box of the given geoms, in world axes or in ``frame``'s: exact half-extents for primitives,
    whose rotated local boxes would overstate them (a capsule rolled by 45 degrees by 41 percent); rotated local
    boxes for meshes."""
    rot = data.geom_xmat[geoms].reshape(-1, 3, 3)
    center = data.geom_xpos[geoms].copy()
    if frame is not None:
        inverse = frame.rotation.T
        rot = np.einsum("ij,njk->nik", inverse, rot)
        center = (center - frame.position) @ inverse.T
    size = model.geom_size[geoms]
    types = model.geom_type[geoms]
    half = np.zeros((len(geoms), 3))
    G = mujoco.mjtGeom
    for kind in np.unique(types):
        sel = types == kind
        r, s = rot[sel], size[sel]
        if kind == int(G.mjGEOM_SPHERE):
            h = np.repeat(s[:, :1], 3, axis=1)
        elif kind == int(G.mjGEOM_BOX):
            h = np.einsum("nij,nj->ni", np.abs(r), s)
        elif kind == int(G.mjGEOM_ELLIPSOID):
            h = np.sqrt(np.einsum("nij,nj->ni", r**2, s**2))
        elif kind == int(G.mjGEOM_CAPSULE):
            h = np.abs(r[:, :, 2]) * s[:, 1:2] + s[:, :1]
        elif kind == int(G.mjGEOM_CYLINDER):
            axis = r[:, :, 2]
            h = np.abs(axis) * s[:, 1:2] + s[:, :1] * np.sqrt(np.clip(1 - axis**2, 0, 1))
        else:  # meshes and the rest: the geom's own box, rotated
            aabb = model.geom_aabb[geoms[sel]]
            corners = aabb[:, None, :3] + _CORNER_SIGNS[None] * aabb[:, None, 3:]
            world = np.einsum("nij,nkj->nki", r, corners)
            lo, hi = world.min(axis=1), world.max(axis=1)
            center[sel] = center[sel] + (lo + hi) / 2
            h = (hi - lo) / 2
        half[sel] = h
    return Box3D((center - half).min(axis=0), (center + half).max(axis=0))


_CIRCLE = np.array([[np.cos(a), np.sin(a)] for a in np.linspace(0, 2 * np.pi, 16, endpoint=False)])
_SPHERE = np.array([[x, y, z] for x in (-1, 0, 1) for y in (-1, 0, 1) for z in (-1, 0, 1) if (x, y, z) != (0, 0, 0)])
_SPHERE = _SPHERE / np.linalg.norm(_SPHERE, axis=1, keepdims=True)


def geoms_outline(model: mujoco.MjModel, data: mujoco.MjData, geoms: np.ndarray) -> np.ndarray:
    """World points, (N, 3), on the geoms' surfaces whose outline seen from above is the geoms' own, however they
    are turned: a ball's is a circle round its centre (the corners of its box would stick out once it rolls), a
    capsule's the circles round its two ends, a cylinder's the rims of its two faces, a box's its corners."""
    out = []
    G = mujoco.mjtGeom
    for g in geoms:
        kind, size = int(model.geom_type[g]), model.geom_size[g]
        center, rotation = data.geom_xpos[g], data.geom_xmat[g].reshape(3, 3)
        if kind in (int(G.mjGEOM_SPHERE), int(G.mjGEOM_CAPSULE)):
            reach = 0.0 if kind == int(G.mjGEOM_SPHERE) else size[1]
            for end in (center - reach * rotation[:, 2], center + reach * rotation[:, 2]):
                out.append(np.column_stack([end[:2] + size[0] * _CIRCLE, np.full(len(_CIRCLE), end[2])]))
        elif kind == int(G.mjGEOM_CYLINDER):
            rim = np.column_stack([size[0] * _CIRCLE, np.zeros(len(_CIRCLE))])
            for face in (-size[1], size[1]):
                out.append(center + (rim + np.array([0.0, 0.0, face])) @ rotation.T)
        elif kind == int(G.mjGEOM_ELLIPSOID):
            out.append(center + (_SPHERE * size[:3]) @ rotation.T)
        else:
            box = kind == int(G.mjGEOM_BOX)
            half, offset = (size[:3], np.zeros(3)) if box else (model.geom_aabb[g, 3:], model.geom_aabb[g, :3])
            out.append(center + (offset + _CORNER_SIGNS * half) @ rotation.T)
    return np.vstack(out) if out else np.zeros((0, 3))


class GroundTruth:
    """Reads the true state of a :class:`SimWorld`."""

    def __init__(self, world: SimWorld):
        self.world = world
        self.model, self.data = world.model, world.data
        self._entity_geoms = {
            e.name: np.array([g for g in range(self.model.ngeom) if self.model.geom_bodyid[g] in e.bodies], dtype=int)
            for e in world.entities
        }
        # The table is its top, where things stand: its legs are under it, and a box down to the floor would put
        # its middle and its bottom where nothing can be done with them.
        top = [g for g in self._entity_geoms["table"] if self.model.geom(g).name == "table/top"]
        self._entity_geoms["table"] = np.array(top, dtype=int)

    def names(self) -> list[str]:
        """The table, furniture, objects and furniture parts, as the tool API lists them."""
        return self.world.spec.query_names()

    def entity(self, name: str) -> Entity:
        return self.world.entity(name)

    def pose(self, name: str) -> Transform:
        """Pose of the entity's (first) body frame; for objects, the centre of their bottom face."""
        body = self.entity(name).bodies[0]
        return Transform.from_mujoco(self.data.xpos[body], self.data.xquat[body])

    def box(self, name: str) -> Box3D:
        """Tight world axis-aligned box around every geom of ``name`` (exact for primitives)."""
        geoms = self._entity_geoms[self.entity(name).name]
        if len(geoms) == 0:
            raise InvalidArgumentError(f"{name!r} has no geometry")
        return geoms_box(self.model, self.data, geoms)

    def local_box(self, name: str, frame: Transform) -> Box3D:
        """Tight box around every geom of ``name`` in the axes of ``frame`` (exact for primitives)."""
        geoms = self._entity_geoms[self.entity(name).name]
        if len(geoms) == 0:
            raise InvalidArgumentError(f"{name!r} has no geometry")
        return geoms_box(self.model, self.data, geoms, frame)

    def outline(self, name: str) -> np.ndarray:
        """Points whose outline from above is that of ``name``'s geoms (see :func:`geoms_outline`)."""
        return geoms_outline(self.model, self.data, self._entity_geoms[self.entity(name).name])

    def geoms(self, name: str) -> np.ndarray:
        """Ids of the geoms that make up ``name``'s shape."""
        return self._entity_geoms[self.entity(name).name]

    def velocity(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """(linear, angular) velocity of the entity's body in the world frame."""
        body = self.entity(name).bodies[0]
        vel = np.zeros(6)
        mujoco.mj_objectVelocity(self.model, self.data, mujoco.mjtObj.mjOBJ_BODY, body, vel, 0)
        return vel[3:], vel[:3]

    def joint(self, name: str) -> JointInfo:
        """The joint of a drawer or door (``cabinet.drawer_1``), or of the part a handle is on."""
        entity = self.entity(name)
        body = entity.bodies[0]
        # A handle has no joint of its own: it moves with its drawer or door.
        while self.model.body_jntnum[body] == 0 and body > 0:
            body = self.model.body_parentid[body]
        if body <= 0:
            raise InvalidArgumentError(f"{name!r} is not articulated; articulated parts: {self._articulated()}")
        j = self.model.body_jntadr[body]
        jtype = int(self.model.jnt_type[j])
        if jtype not in (int(mujoco.mjtJoint.mjJNT_SLIDE), int(mujoco.mjtJoint.mjJNT_HINGE)):
            raise InvalidArgumentError(f"{name!r} moves freely; articulated parts: {self._articulated()}")
        return JointInfo(
            name=self.model.joint(j).name,
            type="prismatic" if jtype == int(mujoco.mjtJoint.mjJNT_SLIDE) else "revolute",
            position=self.data.xanchor[j].copy(),
            axis=self.data.xaxis[j].copy(),
            value=float(self.data.qpos[self.model.jnt_qposadr[j]]),
            lower=float(self.model.jnt_range[j][0]),
            upper=float(self.model.jnt_range[j][1]),
        )

    def compartment(self, door: str) -> tuple[Transform, np.ndarray, np.ndarray]:
        """The compartment behind ``door`` (``cabinet.door_0``): its cabinet's frame and its free inside,
        ``(lower, upper)`` in that frame."""
        body = self.entity(door).bodies[0]
        carcass = int(self.model.body_parentid[body])
        frame = Transform.from_mujoco(self.data.xpos[carcass], self.data.xquat[carcass])
        lower, upper = compartment_interior(self.model, door)
        return frame, lower, upper

    def holding_space(self, name: str) -> tuple[Transform, Box3D]:
        """Where things put into ``name`` are, in its own axes: a door's compartment behind it in its cabinet's
        frame, else ``name``'s own box in the frame of its pose."""
        if self.entity(name).category == "door":
            frame, lower, upper = self.compartment(name)
            return frame, Box3D(np.asarray(lower, dtype=float), np.asarray(upper, dtype=float))
        frame = self.pose(name)
        return frame, self.local_box(name, frame)

    def holding_box(self, name: str) -> Box3D:
        """Where things put into ``name`` are, world-aligned: a door's compartment behind it, else ``name``'s own
        box."""
        if self.entity(name).category != "door":
            return self.box(name)
        frame, inside = self.holding_space(name)
        return Box3D.from_points(frame.apply(inside.corners()))

    def _articulated(self) -> list[str]:
        return [e.name for e in self.world.entities if e.joint >= 0]

    def contacts(self, name: str | None = None) -> list[Contact]:
        """Active contacts, optionally only those touching ``name``."""
        out = []
        force = np.zeros(6)
        for i in range(self.data.ncon):
            c = self.data.contact[i]
            ea, eb = (self._geom_label(g) for g in c.geom)
            if name is not None and name not in (ea, eb):
                continue
            mujoco.mj_contactForce(self.model, self.data, i, force)
            out.append(Contact(ea, eb, c.pos.copy(), c.frame[:3].copy(), float(force[0])))
        return out

    def _geom_label(self, geom: int) -> str:
        index = self.world.geom_entity[geom]
        if index >= 0:
            return self.world.entities[index].name
        return self.model.geom(geom).name or f"geom {geom}"
