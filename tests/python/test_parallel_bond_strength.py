"""A single bond loaded to failure breaks at the load its criteria predict, in the right mode.

Disc 1 is fixed; disc 2's motion is imposed (all its DOFs blocked, velocity set), so the
bond is loaded quasi-statically and the peak bond load is read step by step.
"""
import math

import pytest
from lattice import R, material
from yade import O

from toppling import bonding, scene

TENSION, SHEAR = 2, 3
STEPS_TO_BREAK = 2000  # load increments of 0.05 % of the failure load


def two_discs(mat):
    a = O.bodies.append(scene.disc((0, 0), R, mat, fixed=True))
    b = O.bodies.append(scene.disc((2 * R, 0), R, mat))
    O.bodies[b].state.blockedDOFs = "xyzXYZ"
    O.engines = scene.engines(gravity=(0, 0, 0), timestepper=False)
    O.dt = 1e-6
    assert bonding.bond_within_gap(1e-9) == 1
    return O.bodies[b], O.interactions[a, b].phys


def run_until_break(phys, max_steps=10 * STEPS_TO_BREAK):
    """Step until the bond breaks; returns the law and the bond's (Fn, |Fs|, M) history."""
    law, history = scene.bond_law(), []
    for _ in range(max_steps):
        O.step()
        if law.breakMode:
            return law, history
        history.append((phys.bondNormalForce, phys.bondShearForce.norm(), phys.bondMoment))
    pytest.fail("bond did not break")


def test_pull_breaks_in_tension_at_tensile_strength(empty_scene):
    mat = material(bondTensileStrength=1e6, bondCohesion=1e9)
    disc, phys = two_discs(mat)
    stretch_at_break = mat.bondTensileStrength / phys.bondKn
    disc.state.vel = (stretch_at_break / (STEPS_TO_BREAK * O.dt), 0, 0)
    law, history = run_until_break(phys)
    peak = max(-fn for fn, _, _ in history)
    assert law.breakMode == [TENSION]
    assert peak == pytest.approx(mat.bondTensileStrength * phys.bondArea, rel=0.01)
    assert law.breakEnergy[0] == pytest.approx(0.5 * peak**2 / (phys.bondKn * phys.bondArea), rel=0.01)


def test_bending_breaks_in_tension_at_moment_capacity(empty_scene):
    mat = material(bondTensileStrength=1e6, bondCohesion=1e9)
    disc, phys = two_discs(mat)
    capacity = mat.bondTensileStrength * phys.bondInertia / phys.bondRadius  # sigma_c I / R_bar
    rotation_at_break = capacity / (phys.bondKn * phys.bondInertia)
    disc.state.angVel = (0, 0, rotation_at_break / (STEPS_TO_BREAK * O.dt))
    law, history = run_until_break(phys)
    assert law.breakMode == [TENSION]
    assert max(abs(m) for _, _, m in history) == pytest.approx(capacity, rel=0.01)


@pytest.mark.parametrize("compression", [0.0, 2e6])
def test_shear_breaks_at_mohr_coulomb_strength(empty_scene, compression):
    mat = material(bondTensileStrength=1e9, bondCohesion=1e6, bondFrictionAngle=math.radians(30))
    disc, phys = two_discs(mat)
    if compression:  # first squeeze the bond to a normal stress `compression`, then shear
        squeeze = compression / phys.bondKn
        disc.state.vel = (-squeeze / (200 * O.dt), 0, 0)
        for _ in range(200):
            O.step()
    slip_at_break = (mat.bondCohesion + compression * math.tan(mat.bondFrictionAngle)) / phys.bondKs
    disc.state.vel = (0, slip_at_break / (STEPS_TO_BREAK * O.dt), 0)
    law, history = run_until_break(phys)
    sigma = history[-1][0] / phys.bondArea
    assert sigma == pytest.approx(compression, abs=0.01 * mat.bondCohesion)
    strength = (mat.bondCohesion + sigma * math.tan(mat.bondFrictionAngle)) * phys.bondArea
    assert law.breakMode == [SHEAR]
    assert max(fs for _, fs, _ in history) == pytest.approx(strength, rel=0.01)
