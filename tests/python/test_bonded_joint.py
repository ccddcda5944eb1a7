"""A bonded smooth joint between two discs, pulled apart and sheared: it breaks at its
strength times the joint area A = 2 lambda min(R1, R2) t, records the break, then carries no
tension and only Coulomb friction."""
import math

import pytest
from lattice import R, material
from yade import O
from yade.wrapper import JointSetGeometry, Law2_ScGeom_SmoothJointPhys_SmoothJoint, SmoothJointMat

from toppling.build import bonding, boundary, engines, joints
from toppling.build.discs import disc
from toppling.run.steps import run_steps

SIGMA, COHESION = 2e5, 3e5  # [Pa]
SPEED = 1e-4  # [m/s], slow: the force grows by knA v dt per step


def bonded_pair(friction_deg: float = 0.0):
    """Disc 0 fixed, disc 1 on top, a bonded horizontal smooth joint between them."""
    rock = material()
    O.bodies.append([disc((0, 0), R, rock, fixed=True), disc((0, 2 * R), R, rock)])
    O.engines = engines.engines(gravity=(0, 0, 0))
    bonding.bond_within_gap(1e-9)
    mechanics = SmoothJointMat(normalStiffness=1e11, shearStiffness=1e11, bonded=True,
                               tensileStrength=SIGMA, cohesion=COHESION, frictionAngle=math.radians(friction_deg),
                               thickness=rock.thickness)
    joints.install_joints([(JointSetGeometry(origin=(0, R), dip=0), mechanics)], lo=(-2 * R, -2 * R), hi=(2 * R, 4 * R))
    return O.interactions[0, 1].phys


def drive(velocity, max_steps=200000):
    """Move disc 1 at ``velocity``, not spinning (as a disc inside a block: free, it would roll
    on disc 0 and hardly shear the joint); returns the largest force magnitude on the fixed disc while
    the joint was bonded, and the force on it once it broke and moved on 100 steps."""
    boundary.move([1], velocity)
    O.bodies[1].state.blockedDOFs = "xyzXYZ"
    law = engines.functor(Law2_ScGeom_SmoothJointPhys_SmoothJoint)
    peak = 0.0
    for _ in range(max_steps):
        O.step()
        if law.breakMode:
            break
        peak = max(peak, O.forces.f(0).norm())
    run_steps(100)
    return peak, law, O.forces.f(0)


def test_bonded_joint_breaks_in_tension_at_its_tensile_strength(empty_scene):
    phys = bonded_pair()
    assert phys.area == pytest.approx(2 * R * 1.0)
    peak, law, after = drive((0, SPEED, 0))
    assert list(law.breakMode) == [2]
    assert peak == pytest.approx(SIGMA * phys.area, rel=1e-3)
    assert after.norm() == 0  # open, unbonded: no tension


def test_bonded_joint_breaks_in_shear_at_its_cohesion_then_slides(empty_scene):
    phys = bonded_pair(friction_deg=30)
    peak, law, after = drive((SPEED, 0, 0))
    assert list(law.breakMode) == [3]
    assert peak == pytest.approx(COHESION * phys.area, rel=1e-3)  # no normal stress: c alone
    assert abs(after[0]) <= math.tan(math.radians(30)) * abs(after[1]) + 1e-12
