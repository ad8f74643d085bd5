"""Shape recipes of the object library: each builds an object's convex parts from its real dimensions, in a frame
whose origin is the centre of the object's bottom (:mod:`roboscript.sim.objects` names and sizes them)."""

from __future__ import annotations

import math

import numpy as np

from roboscript.objects.shapes import RGBA, Part, arc_of_capsules, disk, open_box, parts_bounds, ring_wall

COLORS: dict[str, RGBA] = {
    "red": (0.78, 0.08, 0.08, 1.0),
    "dark_red": (0.5, 0.05, 0.08, 1.0),
    "green": (0.15, 0.6, 0.15, 1.0),
    "light_green": (0.55, 0.8, 0.25, 1.0),
    "blue": (0.12, 0.3, 0.8, 1.0),
    "yellow": (0.95, 0.85, 0.15, 1.0),
    "orange": (0.98, 0.55, 0.1, 1.0),
    "purple": (0.42, 0.12, 0.45, 1.0),
    "pink": (0.95, 0.6, 0.6, 1.0),
    "white": (0.93, 0.93, 0.91, 1.0),
    "black": (0.08, 0.08, 0.08, 1.0),
    "gray": (0.5, 0.5, 0.52, 1.0),
    "brown": (0.45, 0.28, 0.14, 1.0),
    "wood": (0.76, 0.6, 0.4, 1.0),
    "tan": (0.82, 0.7, 0.5, 1.0),
    "peach": (0.98, 0.7, 0.5, 1.0),
    "cyan": (0.1, 0.7, 0.8, 1.0),
    "turquoise": (0.15, 0.68, 0.66, 1.0),
    "sand": (0.85, 0.76, 0.6, 1.0),
}


# Walls start this far above the base they stand on, so that only the base touches the table: a wall of 16 box
# segments resting on the table would add 64 contacts and cost a third of the simulation speed.
WALL_LIFT = 0.002


def sphere(radius: float) -> tuple[Part, ...]:
    return (Part("sphere", (radius,), (0.0, 0.0, radius)),)


def ellipsoid(rx: float, ry: float, rz: float) -> tuple[Part, ...]:
    return (Part("ellipsoid", (rx, ry, rz), (0.0, 0.0, rz)),)


def box(lx: float, ly: float, lz: float) -> tuple[Part, ...]:
    return (Part("box", (lx / 2, ly / 2, lz / 2), (0.0, 0.0, lz / 2)),)


def cylinder(radius: float, height: float) -> tuple[Part, ...]:
    return (Part("cylinder", (radius, height / 2), (0.0, 0.0, height / 2)),)


def banana() -> tuple[Part, ...]:
    # A curved chain of capsules lying on the table, about 19 cm long and 3.6 cm thick.
    thickness = 0.018
    arc = arc_of_capsules(0.125, thickness, math.radians(-125), math.radians(-55), 6, (0.0, 0.0, 0.0), "xy")
    # Lift so that the lowest point rests at z = 0; centre the arc on the origin in x, y.
    lower, upper = parts_bounds(arc)
    offset = np.array([-(lower[0] + upper[0]) / 2, -(lower[1] + upper[1]) / 2, thickness])
    tip = (0.35, 0.25, 0.1, 1.0)
    out = []
    for i, p in enumerate(arc):
        ends = i in (0, len(arc) - 1)
        # Like a real banana, it rests on its ends: the middle is lifted a little off the table, which also
        # halves its contacts with the table.
        lift = np.array([0.0, 0.0, 0.0 if ends else 0.0015])
        out.append(Part(p.kind, p.size, tuple(np.array(p.pos) + offset + lift), p.quat, tip if ends else None))
    return tuple(out)


def pear() -> tuple[Part, ...]:
    # Two spheres alone put the centre of mass above the lower one's centre: it would stand only balanced, and
    # fall over when set down. A real pear stands on a flattened bottom, as the disk gives it.
    return (
        Part("cylinder", (0.022, 0.003), (0.0, 0.0, 0.003)),
        Part("sphere", (0.034,), (0.0, 0.0, 0.034)),
        Part("sphere", (0.024,), (0.0, 0.0, 0.07)),
        Part("capsule", (0.003, 0.006), (0.0, 0.0, 0.098), rgba=COLORS["brown"]),
    )


def mug(radius: float, height: float, wall: float = 0.006, accent: RGBA | None = None) -> tuple[Part, ...]:
    """A mug with a handle; ``accent``: the colour of its floor and handle where they differ from its walls."""
    parts = [disk(radius, 0.008, rgba=accent)]
    parts += ring_wall(radius - wall / 2, radius - wall / 2, height - WALL_LIFT, wall, 16, z0=WALL_LIFT)
    # The handle: a C of capsules on the +x side, in the x-z plane.
    handle_r = height * 0.3
    parts += arc_of_capsules(
        handle_r, 0.006, math.radians(-80), math.radians(80), 5, (radius - 0.004, 0.0, height * 0.52), "xz", accent
    )
    return tuple(parts)


def cup(bottom_radius: float, top_radius: float, height: float, wall: float = 0.004) -> tuple[Part, ...]:
    return (
        disk(bottom_radius + wall / 2, 0.006),
        *ring_wall(bottom_radius, top_radius, height - WALL_LIFT, wall, 14, z0=WALL_LIFT),
    )


def bowl(bottom_radius: float, top_radius: float, height: float, z0: float = 0.0) -> tuple[Part, ...]:
    return (
        disk(bottom_radius + 0.004, 0.008, z0),
        *ring_wall(bottom_radius, top_radius, height - WALL_LIFT, 0.007, 16, z0 + WALL_LIFT),
    )


def footed_bowl() -> tuple[Part, ...]:
    foot = disk(0.045, 0.01)
    stem = Part("cylinder", (0.013, 0.02), (0.0, 0.0, 0.03))
    return (foot, stem, *bowl(0.05, 0.095, 0.085, z0=0.05))


def plate(radius: float, rim: float = 0.022, rim_height: float = 0.016) -> tuple[Part, ...]:
    inner = radius - rim
    # The rim starts near the top of the base: a steeply flared rim reaching down to the table would put every
    # segment's bounding box against the table top and into the narrow phase on every step.
    return (disk(inner + 0.004, 0.008), *ring_wall(inner, radius, rim_height - 0.004, 0.005, 16, z0=0.007))


def basket() -> tuple[Part, ...]:
    return tuple(open_box(0.34, 0.26, 0.13, 0.008))


def lined_basket(length: float, width: float, height: float) -> tuple[Part, ...]:
    """A woven basket with a fabric liner: the liner shows on its floor."""
    floor, *walls = open_box(length, width, height, 0.008)
    return (Part(floor.kind, floor.size, floor.pos, floor.quat, COLORS["gray"]), *walls)


def square_plate(side: float, well: float, rim_height: float) -> tuple[Part, ...]:
    """A square plate: a flat well and a raised border around it (a dinner plate with a square rim)."""
    base = Part("box", (well / 2, well / 2, 0.004), (0.0, 0.0, 0.004))
    border = (side - well) / 2
    # The border starts above the table, as round plates' rims do: only the well rests on the table.
    z = 0.004 + rim_height / 2
    half_h = rim_height / 2
    along = (side / 2, border / 2, half_h)
    across = (border / 2, well / 2, half_h)
    offset = (well + border) / 2
    return (
        base,
        Part("box", along, (0.0, offset, z)),
        Part("box", along, (0.0, -offset, z)),
        Part("box", across, (offset, 0.0, z)),
        Part("box", across, (-offset, 0.0, z)),
    )


def flat_bottle(length: float, width: float, height: float, neck_radius: float, cap_rgba: RGBA) -> tuple[Part, ...]:
    """A bottle with a flattened body (a mustard or a cleanser bottle), its neck and cap on top."""
    body_h = height * 0.8
    neck_h = (height - body_h) * 0.55
    cap_h = height - body_h - neck_h
    return (
        Part("box", (length / 2, width / 2, body_h / 2), (0.0, 0.0, body_h / 2)),
        Part("cylinder", (neck_radius, neck_h / 2), (0.0, 0.0, body_h + neck_h / 2)),
        Part("cylinder", (neck_radius * 1.15, cap_h / 2), (0.0, 0.0, height - cap_h / 2), rgba=cap_rgba),
    )


def two_tone_box(lx: float, ly: float, lz: float, band: float, band_rgba: RGBA) -> tuple[Part, ...]:
    """A carton with a coloured band round its top."""
    body = lz - band
    return (
        Part("box", (lx / 2, ly / 2, body / 2), (0.0, 0.0, body / 2)),
        Part("box", (lx / 2, ly / 2, band / 2), (0.0, 0.0, body + band / 2), rgba=band_rgba),
    )


def square_saucer(side: float, depth: float, wall: float) -> tuple[Part, ...]:
    """A square plant saucer: a tray with low walls."""
    return tuple(open_box(side, side, depth, wall))


def bottle(radius: float, height: float, cap_rgba: RGBA) -> tuple[Part, ...]:
    body_h = height * 0.78
    return (
        Part("cylinder", (radius, body_h / 2), (0.0, 0.0, body_h / 2)),
        Part("cylinder", (radius * 0.6, (height - body_h) * 0.3), (0.0, 0.0, body_h + (height - body_h) * 0.3)),
        Part(
            "cylinder",
            (radius * 0.75, (height - body_h) * 0.2),
            (0.0, 0.0, height - (height - body_h) * 0.2),
            rgba=cap_rgba,
        ),
    )


def toy_vehicle(length: float, width: float, height: float, wheel_r: float, cabin: bool) -> tuple[Part, ...]:
    body_h = height - wheel_r
    parts = [
        Part(
            "box",
            (length / 2, width / 2, body_h / 2 * (0.6 if cabin else 1.0)),
            (0.0, 0.0, wheel_r + body_h / 2 * (0.6 if cabin else 1.0)),
        )
    ]
    if cabin:
        parts.append(
            Part(
                "box",
                (length * 0.3, width / 2 * 0.9, body_h * 0.2),
                (-length * 0.1, 0.0, wheel_r + body_h * 0.8),
                rgba=COLORS["cyan"],
            )
        )
    wheel_q = (math.sin(math.pi / 4), 0.0, 0.0, math.cos(math.pi / 4))  # axis along y
    for sx in (-1, 1):
        for sy in (-1, 1):
            parts.append(
                Part(
                    "cylinder",
                    (wheel_r, 0.006),
                    (sx * length * 0.32, sy * (width / 2 - 0.004), wheel_r),
                    wheel_q,
                    COLORS["black"],
                )
            )
    return tuple(parts)


def interior_of_cylinder(radius: float, z0: float, height: float) -> tuple[tuple[float, ...], tuple[float, ...]]:
    r = radius / math.sqrt(2)
    return ((-r, -r, z0), (r, r, z0 + height))
