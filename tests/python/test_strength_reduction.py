"""toppling.load.strength_reduction on examples/verification/strength_reduction.py: a bonded
block across a smooth joint on an incline, against FS = (c A + W cos α tan φ) / (W sin α)."""
import math

import pytest

from conftest import run_example
from lattice import R, material
from yade import O
from yade.wrapper import ParallelBondMat, SmoothJointMat

from toppling.build import bonding, engines
from toppling.build.discs import disc
from toppling.build.engines import broken_bonds
from toppling.load.strength_reduction import Reduction, Search, first_break_factor
from toppling.load.tilting import StageCriteria
from toppling.run.steps import run_steps

EXAMPLE = "examples/verification/strength_reduction.py"


def test_friction_alone_gives_tan_phi_over_tan_alpha(tmp_path):
    s = run_example(EXAMPLE, tmp_path, alpha=20.0, phi=30.0, b=0.2, h=0.1)
    assert s["closed_form"] == pytest.approx(math.tan(math.radians(30)) / math.tan(math.radians(20)))
    low, high = s["bracket"]
    assert high - low <= 0.02 and abs(s["factor_of_safety"] - s["closed_form"]) <= 0.02
    assert s["mode_at_failure"] == "slide"
    assert [t["failed"] for t in s["trials"]][:3] == [False, False, False]  # 1, 1.25, 1.5625 stand


def test_joint_cohesion_raises_the_factor_but_fails_progressively(tmp_path):
    """A cemented joint's contacts break one by one (brittle, under uneven stresses: a few
    contacts across a rough joint), so the block fails before c A + W cos α tan φ is mobilised:
    the factor lies above the frictional one and below the closed form (docs/verification.md)."""
    s = run_example(EXAMPLE, tmp_path, alpha=20.0, phi=20.0, cohesion=800.0, b=0.3, h=0.05, joint_stiffness_scale=0.01)
    frictional = 1.0  # tan 20 / tan 20
    assert frictional + 0.5 < s["factor_of_safety"] <= s["closed_form"]
    assert s["mode_at_failure"] == "slide"


def test_a_toppling_block_has_no_factor_of_safety_and_says_so(tmp_path):
    s = run_example(EXAMPLE, tmp_path, alpha=30.0, phi=40.0, b=0.05, h=0.2)  # b/h = 0.25 < tan 30 < tan 40
    assert s["factor_of_safety"] is None and s["trials"][0]["failed"]
    assert s["mode_at_failure"] == "topple"


def test_reduction_divides_tan_phi_or_the_angle_and_refuses_other_modes():
    assert Reduction().tan_friction(0.6, 2.0) == pytest.approx(0.3)
    assert Reduction(friction="angle").angle(math.radians(40), 2.0) == pytest.approx(math.radians(20))
    assert Reduction(friction="none").tan_friction(0.6, 2.0) == 0.6
    with pytest.raises(ValueError, match="friction = 'sin' is invalid"):
        Reduction(friction="sin")
    with pytest.raises(ValueError, match=r"growth = 1.0 is invalid: it must be in \(1, inf\)"):
        Search("x.yade", [[0]], StageCriteria(), growth=1.0)


def test_bonds_scope_divides_the_bonds_alone(empty_scene):
    rock = O.materials.append(ParallelBondMat(bondTensileStrength=1e6, bondCohesion=2e6, bondFrictionAngle=0.4,
                                              frictionAngle=0.3))
    joint = O.materials.append(SmoothJointMat(frictionAngle=0.5, tensileStrength=1e5, cohesion=1e5))
    Reduction(friction="angle", scope="bonds").apply(2.0)
    rock, joint = O.materials[rock], O.materials[joint]
    assert (rock.bondTensileStrength, rock.bondCohesion) == (5e5, 1e6)
    assert rock.bondFrictionAngle == pytest.approx(0.2) and rock.frictionAngle == pytest.approx(0.3)
    assert (joint.frictionAngle, joint.tensileStrength, joint.cohesion) == (0.5, 1e5, 1e5)
    with pytest.raises(ValueError, match="scope = 'joints' is invalid"):
        Reduction(scope="joints")


@pytest.mark.parametrize("force", [(2e3, 0.0), (0.0, 1e3)])  # pulled; pushed sideways (shear and bending)
def test_a_bond_holds_just_below_its_first_break_factor_and_breaks_just_above(empty_scene, force):
    mat = material()
    mat.bondTensileStrength, mat.bondCohesion = 1e6, 1e6
    fixed, loaded = (O.bodies.append(disc((x, 0), R, mat, fixed=x == 0)) for x in (0, 2 * R))
    O.engines = engines.engines(gravity=(0, 0, 0), local_damping=0.7)
    bonding.bond_within_gap(0.01 * R)
    O.forces.setPermF(loaded, (force[0], force[1], 0))
    run_steps(20000)  # to rest under the load
    reduction = Reduction()
    first = first_break_factor(reduction)
    assert 1 < first < 100
    O.saveTmp("loaded")
    for factor, breaks in ((0.98 * first, 0), (1.02 * first, 1)):
        O.loadTmp("loaded")
        reduction.apply(factor)
        run_steps(200)
        assert broken_bonds() == breaks
