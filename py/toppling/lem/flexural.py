"""Flexural toppling by limit equilibrium (Aydan and Kawamoto 1992; thesis §2.4.1, eqs. 2-3, 2-4).

Each column between two main joints is a cantilever on the fracture plane (``failure_plane_deg``
above the normal to the joints: 0° in Aydan and Kawamoto, 10° as calibrated by Adhikary et al.
1997). Working down from the top column, the side force ``P[j-1]`` that column j needs from the
column below is the one that keeps the tensile stress at its base at the rock's tensile strength:

    P[j-1] = (max(P[j], 0) (x h[j] - μ b / 2) + T h̄ / 2 - (2 I / b) (σt + N / b)) / (x h[j-1] + μ b / 2)

with b the column's thickness (the joint spacing), h[j-1] and h[j] its lower and upper side
lengths, h̄ = (h[j-1] + h[j]) / 2, I = b³ / 12, W = γ b h̄, N = W sin δ along the column and
T = W cos δ across it (δ the joints' dip), μ = tan φ of the joints, and the side force acting at
x h (x = 0.6 after Adhikary et al. 1997). The thesis prints I = b/12 and h̄ = ½ (h[j] + h[j-1]) as
a definition of h; both are typos. P[0] > 0: unstable, = 0: limiting, < 0: stable.

Units: m, degrees, N/m³ and Pa (or kN/m³ and kPa), forces per metre of slope.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from toppling.checks import require
from toppling.lem.geometry import SlopeGeometry


def base_tension(unit_weight: float, width: float, height: float, tilt_deg: float) -> float:
    """Beam theory's tensile stress at the base of a free-standing column ``width`` × ``height``
    tilted by ``tilt_deg``: bending 3 γ h² sin α / b less the weight's compression γ h cos α."""
    a = math.radians(tilt_deg)
    return 3 * unit_weight * height**2 * math.sin(a) / width - unit_weight * height * math.cos(a)


def breaking_tilt(unit_weight: float, width: float, height: float, strength: float) -> float:
    """The tilt [deg] at which ``base_tension`` reaches ``strength``: A sin α − B cos α = σ, so
    α = asin(σ / √(A² + B²)) + atan(B / A)."""
    bend, weight = 3 * unit_weight * height**2 / width, unit_weight * height
    reach = math.hypot(bend, weight)
    if strength > reach:
        raise ValueError(f"strength = {strength} is invalid: the column's base tension never exceeds {reach:g} Pa")
    return math.degrees(math.asin(strength / reach) + math.atan2(weight, bend))

@dataclass(frozen=True)
class Rock:
    unit_weight: float  # γ
    tensile_strength: float  # σt
    friction_deg: float  # φ of the main joints
    side_force_at: float = 0.6  # x

    def __post_init__(self):
        require("unit_weight", self.unit_weight, "(0, inf)")
        require("tensile_strength", self.tensile_strength, "[0, inf)")
        require("friction_deg", self.friction_deg, "[0, 90)")
        require("side_force_at", self.side_force_at, "(0, 1)")

    def reduced(self, factor: float) -> "Rock":
        """Tensile strength and tan φ divided by ``factor``."""
        friction = math.degrees(math.atan(math.tan(math.radians(self.friction_deg)) / factor))
        return Rock(self.unit_weight, self.tensile_strength / factor, friction, self.side_force_at)


def side_forces(slope: SlopeGeometry, rock: Rock) -> list[float]:
    """P[0] … P[N-1], toe first: the force each column needs from the one below it."""
    h, forces, p_above = slope.side_lengths(), [], 0.0
    for j in range(len(h) - 1, 0, -1):
        p_above = column_force(p_above, h[j - 1], h[j], slope.spacing, slope.joint_dip_deg, rock)
        forces.append(p_above)
    return forces[::-1]


def column_force(p_above: float, lower: float, upper: float, thickness: float, joint_dip_deg: float,
                 rock: Rock) -> float:
    """Eq. 2-4 for one column: the force from the column below that holds the base's tensile
    stress at the strength, given the force ``p_above`` from the column above (only a push
    counts) and the side lengths ``lower`` and ``upper``."""
    b, delta, x = thickness, math.radians(joint_dip_deg), rock.side_force_at
    mu, mean = math.tan(math.radians(rock.friction_deg)), (lower + upper) / 2
    weight = rock.unit_weight * b * mean
    moment = (max(p_above, 0.0) * (x * upper - mu * b / 2) + weight * math.cos(delta) * mean / 2
              - 2 * (b ** 3 / 12) / b * (rock.tensile_strength + weight * math.sin(delta) / b))
    lever = x * lower + mu * b / 2
    if lever > 0:
        return moment / lever
    return math.inf if moment > 0 else 0.0


def toe_force(slope: SlopeGeometry, rock: Rock) -> float:
    """P0: > 0 the slope needs support at the toe (unstable), < 0 it stands with a margin."""
    return side_forces(slope, rock)[0]


def factor_of_safety(slope: SlopeGeometry, rock: Rock, tolerance: float = 1e-4) -> float:
    """The factor F that, dividing the tensile strength and tan φ alike, brings P0 to 0: doubled
    (or halved) from 1 until P0 changes sign, then bisected."""
    def fails(factor: float) -> bool:
        return toe_force(slope, rock.reduced(factor)) > 0

    low = high = 1.0
    while not fails(high):
        low, high = high, high * 2
        if high > 1e6:
            raise ValueError("the slope stands with its strengths divided by 1e6: no factor of safety")
    while fails(low):
        low, high = low / 2, low
        if low < 1e-6:
            raise ValueError("the slope fails with its strengths multiplied by 1e6: no factor of safety")
    while high - low > tolerance * low:
        mid = math.sqrt(low * high)
        low, high = (mid, high) if not fails(mid) else (low, mid)
    return math.sqrt(low * high)


def summary(slope: SlopeGeometry, rock: Rock, per_column: bool = False) -> dict:
    """P0, whether the slope stands, the factor of safety (None with a ``note`` where none is
    found); ``per_column``: the side forces and lengths too."""
    forces = side_forces(slope, rock)
    out = dict(toe_force=forces[0], stable=forces[0] < 0, factor_of_safety=None)
    try:
        out["factor_of_safety"] = factor_of_safety(slope, rock)
    except ValueError as error:
        out["note"] = str(error)
    if per_column:
        out.update(side_forces=forces, side_lengths=slope.side_lengths())
    return out
