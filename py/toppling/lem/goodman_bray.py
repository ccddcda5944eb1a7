"""Block toppling on a stepped base by limit equilibrium (Goodman and Bray 1976).

The blocks are rectangular columns of width ``width`` standing on steps whose treads dip at
``base_dip_deg`` (ψp; the block sides dip at 90° − ψp into the slope), numbered from the toe.
Working down from the top block, each block passes to the block below the force ``P[n-1]`` that
keeps it from toppling (``P_topple``) or from sliding (``P_slide``), whichever is larger, or
nothing when it stands on its own; the force left at the toe, ``P[0]``, is the support the toe
needs. The equations are those of Hoek and Bray (1981, *Rock Slope Engineering*, 3rd ed., §10)
and Wyllie and Mah (2004, *Rock Slope Engineering*, 4th ed., §9.4.3, eqs. 9.16-9.20):

* toppling: ``P[n-1] = (P[n] (M[n] - Δx tan φd) + W/2 (y sin ψp - Δx cos ψp)) / L[n]``
* sliding: ``P[n-1] = P[n] - W (tan φp cos ψp - sin ψp) / (1 - tan φp tan φd)``
* base forces: ``R = W cos ψp + (P[n] - P[n-1]) tan φd``, ``S = W sin ψp + (P[n] - P[n-1])``

with ``W = γ y Δx`` (per unit length of slope) and the lever arms of the side forces measured
from the block's base: below the crest ``M = y``, ``L = y - a1``; at the crest ``M = y - a2``,
``L = y - a1``; above it ``M = y - a2``, ``L = y``. A block is classed by the forces, not by its
own shape: a squat block (y/Δx < cot ψp) pushed from above topples when ``P_topple`` governs.

Units: lengths in m, angles in degrees, ``unit_weight`` in N/m³ (or kN/m³), forces in N (or kN)
per metre of slope.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from toppling.checks import require

STABLE, TOPPLING, SLIDING = "stable", "toppling", "sliding"


@dataclass(frozen=True)
class Blocks:
    """Heights toe first [m], width Δx [m], base dip ψp [°], the face and top steps a1, a2 [m]
    (a1 = Δx tan(ψf − ψp), a2 = Δx tan(ψp − ψs)), unit weight [N/m³]; ``crest`` is the number of
    the crest block (1-based), by default the tallest."""
    heights: tuple[float, ...]
    width: float
    base_dip_deg: float
    a1: float
    a2: float
    unit_weight: float
    crest: int = 0

    def __post_init__(self):
        if len(self.heights) < 1:
            raise ValueError("heights = [] is invalid: give at least one block")
        for n, height in enumerate(self.heights, 1):
            require(f"heights[{n}]", height, "(0, inf)")
        require("width", self.width, "(0, inf)")
        require("unit_weight", self.unit_weight, "(0, inf)")
        require("base_dip_deg", self.base_dip_deg, "(0, 90)")
        require("a1", self.a1, "[0, inf)")
        require("a2", self.a2, "[0, inf)")
        require("crest", self.crest, f"whole [0, {len(self.heights)}]")  # 0: the tallest block

    @property
    def crest_block(self) -> int:
        return self.crest or 1 + self.heights.index(max(self.heights))

    def lever_arms(self, n: int) -> tuple[float, float]:
        """(M, L): heights above block n's base where the forces from the blocks above and below act."""
        y, crest = self.heights[n - 1], self.crest_block
        return (y if n < crest else y - self.a2), (y if n > crest else y - self.a1)


@dataclass(frozen=True)
class Block:
    number: int
    height: float
    mode: str
    p_topple: float  # force on the block below that keeps this one from toppling
    p_slide: float  # ... from sliding
    p_below: float  # the force passed on: max(p_topple, p_slide, 0)
    normal: float  # R, base normal force
    shear: float  # S, base shear force


@dataclass(frozen=True)
class Result:
    blocks: list[Block]  # toe first
    friction_deg: float

    @property
    def toe_force(self) -> float:
        """P0: the support the toe block needs; 0 when the slope stands by itself."""
        return self.blocks[0].p_below

    @property
    def modes(self) -> list[str]:
        return [b.mode for b in self.blocks]


def analyse(blocks: Blocks, friction_deg: float, base_friction_deg: float | None = None) -> Result:
    """The forces block by block for side friction φd = ``friction_deg`` and base friction
    φp = ``base_friction_deg`` (default φd)."""
    phi_p = friction_deg if base_friction_deg is None else base_friction_deg
    require("friction_deg", friction_deg, "[0, 90)")
    require("base_friction_deg", phi_p, "[0, 90)")
    psi, dx = math.radians(blocks.base_dip_deg), blocks.width
    tan_d, tan_p = math.tan(math.radians(friction_deg)), math.tan(math.radians(phi_p))
    p_above, out = 0.0, []
    for n in range(len(blocks.heights), 0, -1):
        y = blocks.heights[n - 1]
        weight = blocks.unit_weight * y * dx
        m_arm, l_arm = blocks.lever_arms(n)
        tipping = p_above * (m_arm - dx * tan_d) + weight / 2 * (y * math.sin(psi) - dx * math.cos(psi))
        p_topple = _holding_force(tipping, l_arm)
        p_slide = _sliding_force(p_above, weight, psi, tan_p, tan_d)
        p_below = max(p_topple, p_slide, 0.0)
        mode = STABLE if p_below == 0 else TOPPLING if p_topple >= p_slide else SLIDING
        out.append(Block(n, y, mode, p_topple, p_slide, p_below,
                         normal=weight * math.cos(psi) + (p_above - p_below) * tan_d,
                         shear=weight * math.sin(psi) + (p_above - p_below)))
        p_above = p_below
    return Result(out[::-1], friction_deg)


def _holding_force(tipping_moment: float, lever: float) -> float:
    """The side force at ``lever`` that balances ``tipping_moment`` about the block's toe; a
    block that tips with no lower neighbour to lean on (lever <= 0) cannot be held."""
    if lever > 0:
        return tipping_moment / lever
    return math.inf if tipping_moment > 0 else 0.0


def _sliding_force(p_above: float, weight: float, psi: float, tan_p: float, tan_d: float) -> float:
    """The side force that keeps the block from sliding; a block whose base and side friction
    together lock it (tan φp tan φd >= 1) cannot slide."""
    if tan_p * tan_d >= 1:
        return -math.inf
    return p_above - weight * (tan_p * math.cos(psi) - math.sin(psi)) / (1 - tan_p * tan_d)


def limiting_friction(blocks: Blocks, tolerance_deg: float = 1e-4) -> float:
    """The friction angle (sides and base alike) at which the toe needs no support (P0 = 0), by
    bisection below 45°: P0 falls as friction rises, and at 45° the sliding equation's
    denominator 1 − tan φp tan φd vanishes (the equations hold below it only)."""
    low, high = 0.0, 45.0 - 1e-6
    if analyse(blocks, low).toe_force == 0:
        return 0.0
    if analyse(blocks, high).toe_force > 0:
        raise ValueError("the toe needs support at every friction angle below 45 degrees, where Goodman and Bray's "
                         "sliding equation holds (tan phi_p tan phi_d < 1): no limiting friction angle")
    while high - low > tolerance_deg:
        mid = (low + high) / 2
        low, high = (mid, high) if analyse(blocks, mid).toe_force > 0 else (low, mid)
    return high


def factor_of_safety(blocks: Blocks, friction_deg: float) -> float:
    """tan φ / tan φ_limit: the factor by which the friction could be divided before the toe needs
    support (inf when the blocks stand without friction)."""
    limit = limiting_friction(blocks)
    return math.tan(math.radians(friction_deg)) / math.tan(math.radians(limit)) if limit > 0 else math.inf


def summary(blocks: Blocks, friction_deg: float, base_friction_deg: float | None = None,
            per_block: bool = False) -> dict:
    """Toe force, modes, limiting friction and factor of safety (where no friction below 45° holds
    the toe, the last two are None and ``note`` says why); ``per_block``: each block's forces too."""
    result = analyse(blocks, friction_deg, base_friction_deg)
    out = dict(toe_force=result.toe_force, modes=result.modes, limiting_friction_deg=None, factor_of_safety=None)
    try:
        out["limiting_friction_deg"] = limiting_friction(blocks)
        out["factor_of_safety"] = factor_of_safety(blocks, friction_deg)
    except ValueError as error:
        out["note"] = str(error)
    if per_block:
        out["blocks"] = [vars(b) for b in result.blocks]
    return out


def toe_support(blocks: Blocks, friction_deg: float, required_fs: float) -> float:
    """P0 with the friction reduced to tan φ / ``required_fs``: the toe force (acting as P0, parallel
    to the base steps) that gives the slope that factor of safety."""
    require("required_fs", required_fs, "(0, inf)")
    reduced = math.degrees(math.atan(math.tan(math.radians(friction_deg)) / required_fs))
    return analyse(blocks, reduced).toe_force
