"""Discs: YADE spheres that move in the xy-plane with the mass and inertia of a disc."""
from __future__ import annotations

import math
from typing import Iterable, Sequence

from yade import O, utils

from toppling.checks import require

PLANE_DOFS = 'zXY'  # discs move in the xy-plane and spin about z only


def disc(center: Sequence[float], radius: float, material, fixed: bool = False):
    """A YADE sphere standing for a disc of the material's thickness t.

    Mass and inertia are the disc's, rho*pi*R^2*t and m*R^2/2 (not the sphere's), so that
    2D dynamics match PFC2D/HDPAC.
    """
    require("radius", radius, "(0, inf)")
    body = utils.sphere((center[0], center[1], 0.0), radius, material=material, fixed=fixed)
    set_disc_mass(body, material.thickness)
    if not fixed:
        body.state.blockedDOFs = PLANE_DOFS
    return body


def set_disc_mass(body, thickness: float) -> None:
    """Give a sphere body the mass and polar inertia of a disc of the given thickness."""
    radius = body.shape.radius
    mass = body.material.density * math.pi * radius**2 * thickness
    body.state.mass = mass
    inertia = 0.5 * mass * radius**2
    body.state.inertia = (inertia, inertia, inertia)


def add_discs(discs: Iterable[tuple[float, float, float]], material) -> list[int]:
    """Add discs given as (x, y, radius); returns their ids."""
    return O.bodies.append([disc((x, y), r, material) for x, y, r in discs])
