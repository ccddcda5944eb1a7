"""Factor of safety by strength reduction: the factor F by which the rock's and the joints'
strengths can be divided before the scene fails.

Each trial loads one equilibrated checkpoint, divides the strengths by F (``Reduction``: bond
and bonded-joint tensile strength and cohesion; friction as tan φ / F, or as the angle φ / F,
as the thesis did for Galandrood, §5.4.2), and runs the watched groups of discs to equilibrium
or failure with the tilting table's criteria (``toppling.load.tilting.stage_outcome``), rest
not being accepted before ``min_time`` (a trial just above the critical factor starts from
rest and accelerates slowly). The search brackets F from 1 by ``growth`` (up when F = 1 stands,
down when it fails) and bisects the bracket to ``tolerance``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable, Sequence

import numpy as np
from yade import O
from yade.wrapper import ParallelBondMat, ParallelBondPhys, SmoothJointMat, SmoothJointPhys

from toppling.build.engines import broken_bonds
from toppling.checks import require
from toppling.load import tilting
from toppling.run.steps import run_checked

FRICTION = ("tan", "angle", "none")
SCOPES = ("all", "bonds")


@dataclass(frozen=True)
class Reduction:
    """What F divides: tensile strengths and cohesions (``strengths``), and friction
    (``friction``: "tan" divides tan φ, "angle" divides φ, "none" leaves it); of everything
    (``scope`` "all": bonds, disc contacts, joints) or of the parallel bonds alone ("bonds": their
    tensile strength, cohesion and friction angle, as the thesis' Table 5-16)."""
    strengths: bool = True
    friction: str = "tan"
    scope: str = "all"

    def __post_init__(self):
        if self.friction not in FRICTION:
            raise ValueError(f"friction = {self.friction!r} is invalid: it must be one of {FRICTION}")
        if self.scope not in SCOPES:
            raise ValueError(f"scope = {self.scope!r} is invalid: it must be one of {SCOPES}")

    def tan_friction(self, tan_phi: float, factor: float) -> float:
        if self.friction == "tan":
            return tan_phi / factor
        if self.friction == "angle":
            return math.tan(math.atan(tan_phi) / factor)
        return tan_phi

    def angle(self, phi: float, factor: float) -> float:
        return math.atan(self.tan_friction(math.tan(phi), factor))

    def apply(self, factor: float) -> None:
        """Divide the strengths of every material (for contacts made from now on) and every
        interaction (those that exist) by ``factor``: once, on a freshly loaded scene."""
        require("factor", factor, "(0, inf)")
        strength = factor if self.strengths else 1.0
        rest = factor if self.scope == "all" else 1.0  # what bonds alone leave as it is
        joint = strength if self.scope == "all" else 1.0
        for mat in O.materials:
            if isinstance(mat, ParallelBondMat):
                mat.bondTensileStrength, mat.bondCohesion = mat.bondTensileStrength / strength, mat.bondCohesion / strength
                mat.frictionAngle, mat.bondFrictionAngle = self.angle(mat.frictionAngle, rest), \
                    self.angle(mat.bondFrictionAngle, factor)
            elif isinstance(mat, SmoothJointMat):
                mat.tensileStrength, mat.cohesion = mat.tensileStrength / joint, mat.cohesion / joint
                mat.frictionAngle = self.angle(mat.frictionAngle, rest)
        for i in O.interactions:
            phys = i.phys
            if isinstance(phys, ParallelBondPhys):
                phys.bondTensileStrength, phys.bondCohesion = phys.bondTensileStrength / strength, \
                    phys.bondCohesion / strength
                phys.bondTanFriction = self.tan_friction(phys.bondTanFriction, factor)
            elif isinstance(phys, SmoothJointPhys):
                phys.tensileStrength, phys.cohesion = phys.tensileStrength / joint, phys.cohesion / joint
            else:
                continue
            phys.tangensOfFrictionAngle = self.tan_friction(phys.tangensOfFrictionAngle, rest)


def first_break_factor(reduction: Reduction) -> float:
    """The smallest F at which ``reduction`` would break an intact parallel bond of the scene as it
    stands (its last step's stresses held): below it, dividing the strengths changes nothing, and
    a scene at rest stays at rest. Tension: σ_max ≥ σ_t / F; shear: τ ≥ c / F + σ tan φ(F), where
    σ is the bond's mean normal stress (compression positive). inf without intact bonds."""
    first = math.inf
    for i in O.interactions:
        phys = i.phys
        if not isinstance(phys, ParallelBondPhys) or phys.bondState != 1:
            continue
        if phys.bondSigmaMax > 0:
            first = min(first, phys.bondTensileStrength / phys.bondSigmaMax if reduction.strengths else math.inf)
        first = min(first, _shear_break_factor(reduction, phys))
    return first


def _shear_break_factor(reduction: Reduction, phys) -> float:
    """The F at which the bond's shear strength falls to its shear stress (bisection: the strength
    falls as F grows), inf if it never does below 1e6."""
    sigma = phys.bondNormalForce / phys.bondArea

    def strength(f: float) -> float:
        cohesion = phys.bondCohesion / (f if reduction.strengths else 1.0)
        return cohesion + sigma * reduction.tan_friction(phys.bondTanFriction, f)
    low, high = 1e-6, 1e6
    if strength(high) > phys.bondTauMax:
        return math.inf
    if strength(low) <= phys.bondTauMax:
        return low
    while high / low > 1 + 1e-9:
        mid = math.sqrt(low * high)
        low, high = (mid, high) if strength(mid) > phys.bondTauMax else (low, mid)
    return high


@dataclass(frozen=True)
class Trial:
    factor: float
    failed: bool
    displacement: float  # [m] the largest median displacement of a watched group
    breaks: int  # parallel bonds broken during the trial (cemented joint contacts not counted)
    time: float  # [s] simulated


@dataclass
class Search:
    """Strength reduction from the equilibrated scene in ``checkpoint`` (a file ``O.save`` wrote),
    watching ``groups`` (lists of body ids: a column's top, a block)."""
    checkpoint: str
    groups: Sequence[Sequence[int]]
    criteria: tilting.StageCriteria
    reduction: Reduction = field(default_factory=Reduction)
    tolerance: float = 0.02  # the bracket's width at the end
    growth: float = 1.25  # the factor between trials while bracketing
    min_time: float = 0.1  # [s] no rest accepted before this
    max_factor: float = 100.0
    on_trial: Callable[[Trial], None] = print
    trials: list[Trial] = field(default_factory=list)

    def __post_init__(self):
        require("tolerance", self.tolerance, "(0, 1)")
        require("growth", self.growth, "(1, inf)")
        require("min_time", self.min_time, "[0, inf)")
        require("max_factor", self.max_factor, "(1, inf)")

    def trial(self, factor: float) -> Trial:
        O.load(self.checkpoint)
        self.reduction.apply(factor)
        reference, watch = tilting.medians(self.groups), tilting.Watch(self.groups, self.criteria)
        start, broken = O.time, broken_bonds()
        while True:
            run_checked(self.criteria.chunk, f"the trial at F = {factor:g}")
            (now, before), elapsed = watch.chunk_done(), O.time - start
            outcome = tilting.stage_outcome(now, before, reference, elapsed, self.criteria)
            if outcome == "failed" or (outcome == "equilibrium" and elapsed >= self.min_time):
                break
        moved = float(np.linalg.norm(now - reference, axis=1).max())
        trial = Trial(factor, outcome == "failed", moved, broken_bonds() - broken, elapsed)
        self.trials.append(trial)
        self.on_trial(trial)
        if trial.failed:
            O.saveTmp("strength_reduction_failed")  # the mechanism at the first failing factor
        return trial

    def bracket(self) -> tuple[float, float]:
        """(last stable, first failing) factors, stepping from 1 by ``growth``."""
        first = next((t for t in self.trials if t.factor == 1.0), None) or self.trial(1.0)
        factor, failed = 1.0, first.failed
        while True:
            step = factor / self.growth if failed else factor * self.growth
            if not 1 / self.max_factor <= step <= self.max_factor:
                state = "fails" if failed else "stands"
                raise RuntimeError(f"the scene {state} at every factor from 1 to {step:g}: no factor of safety in "
                                   f"[{1 / self.max_factor:g}, {self.max_factor:g}] (max_factor)")
            if self.trial(step).failed != failed:
                return (step, factor) if failed else (factor, step)
            factor = step

    def run(self) -> tuple[float, float]:
        """The final bracket (last stable, first failing factor), ``tolerance`` wide or less; the
        scene is left as the first failing trial ended."""
        low, high = self.bracket()
        while high - low > self.tolerance:
            mid = (low + high) / 2
            low, high = (low, mid) if self.trial(mid).failed else (mid, high)
        if self.trials[-1].factor != high:
            O.loadTmp("strength_reduction_failed")
        return low, high
