"""Boundary conditions on discs near boundary segments (thesis §3.2.3)."""
from __future__ import annotations

import math
from typing import Iterable, Sequence

from yade import O

from toppling.checks import require

Point = Sequence[float]


def _distance(p: Point, a: Point, b: Point) -> float:
    dx, dy = b[0] - a[0], b[1] - a[1]
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2))
    return math.hypot(p[0] - (a[0] + t * dx), p[1] - (a[1] + t * dy))


def near(segments: Iterable[tuple[Point, Point]], distance: float, ids: Sequence[int] | None = None) -> list[int]:
    """Discs whose centre lies within ``distance`` (the thesis uses Rmax) of any segment."""
    require("distance", distance, "[0, inf)")
    segments = list(segments)
    bodies = O.bodies if ids is None else [O.bodies[i] for i in ids]
    return [b.id for b in bodies
            if b is not None and any(_distance(b.state.pos, a, c) <= distance for a, c in segments)]


def is_held(body) -> bool:
    """Whether a boundary condition prescribes the body's motion: not dynamic, or x or y blocked
    (a fixed layer, a platen)."""
    return not body.dynamic or bool(set(body.state.blockedDOFs) & {"x", "y"})


def fix(ids: Iterable[int], dofs: str = "xy") -> None:
    """Hold the discs' x (``dofs='x'``) or x and y (``'xy'``) still; rotation stays free."""
    if dofs not in ("x", "y", "xy"):
        raise ValueError(f"dofs = {dofs!r} is invalid: it must be 'x', 'y' or 'xy'")
    move(ids, (0.0, 0.0), dofs)


def move(ids: Iterable[int], velocity: Sequence[float], dofs: str = "xy") -> None:
    """Impose a velocity on the discs' ``dofs`` (platens); other DOFs stay as they were."""
    for i in ids:
        state = O.bodies[i].state
        state.blockedDOFs = "".join(sorted(set(state.blockedDOFs) | set(dofs) | {"z", "X", "Y"}))
        vel = list(state.vel)
        for axis, k in (("x", 0), ("y", 1)):
            if axis in dofs:
                vel[k] = velocity[k]
        state.vel = vel
