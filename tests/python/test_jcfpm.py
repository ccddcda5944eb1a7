"""Our scene handed to YADE's JCFpm: the material mapping, every pair kept, the same bond strength."""
import math

import pytest
from lattice import R, material
from test_smooth_joint import acceleration, block_on_slab, tilt
from yade import O
from yade.wrapper import JCFpmPhys, ParallelBondMat

from toppling.build import bonding, engines, jcfpm
from toppling.build.discs import disc
from toppling.run.steps import run_steps

G = engines.G


def bonded_pair(rock: ParallelBondMat):
    a = O.bodies.append(disc((0, 0), R, rock, fixed=True))
    b = O.bodies.append(disc((2 * R, 0), R, rock))
    O.engines = engines.engines(gravity=(0, 0, 0), timestepper=False)
    bonding.bond_within_gap(1e-9 * R)
    return a, b


def test_the_material_gives_a_pair_of_the_reference_radius_our_stiffness_and_strength(empty_scene):
    rock = material(young=2e9, knKs=1.5, bondTensileStrength=3e6, bondCohesion=5e6, bondRadiusMultiplier=0.8)
    ours = O.interactions[bonded_pair(rock)].phys
    mat = jcfpm.material(rock, None, R)
    kn = 2 * mat.young * R * R / (R + R)  # JCFpm's Ip2 for two discs of radius R
    assert kn == pytest.approx(ours.kn, rel=1e-12)
    assert mat.poisson * kn == pytest.approx(ours.ks, rel=1e-12)
    cross_section = math.pi * R**2
    assert mat.tensileStrength * cross_section == pytest.approx(rock.bondTensileStrength * ours.bondArea, rel=1e-12)
    assert mat.cohesion * cross_section == pytest.approx(rock.bondCohesion * ours.bondArea, rel=1e-12)


@pytest.mark.parametrize("load", ["pull", "shear"])
def test_a_bond_breaks_at_the_same_force_in_both_models(empty_scene, load):
    # Pulled, both criteria give min(sigma_c, c / tan phi_bar) A: Mohr-Coulomb's line reaches zero
    # shear strength before the tension cut-off here; sheared at no normal force, c A.
    rock = material(bondTensileStrength=2e6, bondCohesion=1e6, bondFrictionAngle=math.radians(30))
    a, b = bonded_pair(rock)
    area = O.interactions[a, b].phys.bondArea
    expected = (min(2e6, 1e6 / math.tan(math.radians(30))) if load == "pull" else 1e6) * area
    jcfpm.convert()
    phys = O.interactions[a, b].phys
    assert isinstance(phys, JCFpmPhys) and phys.isCohesive
    moving = O.bodies[b].state
    moving.blockedDOFs = "xyzXYZ"
    O.dt = 0.1 * math.sqrt(moving.mass / phys.kn)
    speed = expected / (phys.kn if load == "pull" else phys.ks) / (1000 * O.dt)  # ~1000 steps to break
    moving.vel = (speed, 0, 0) if load == "pull" else (0, speed, 0)
    peak = 0.0
    while O.interactions.has(a, b) and O.interactions[a, b].isReal and O.interactions[a, b].phys.isCohesive:
        run_steps(1)
        peak = max(peak, O.forces.f(b).norm())
        assert O.iter < 5000, "the bond did not break"
    assert peak == pytest.approx(expected, rel=0.005)


def test_every_bond_and_joint_pair_is_kept_and_read_as_ours(empty_scene):
    block_on_slab(friction_deg=20)
    ours = {(i.id1, i.id2): i.phys for i in O.interactions if i.isReal}
    kinds = {pair: jcfpm.pair_of(O.interactions[pair]).kind for pair in ours}
    counts = jcfpm.convert()
    assert counts["misread"] == 0
    assert counts["joint"] == 16 and counts["bond"] == sum(k == "bond" for k in kinds.values())
    for pair, phys in ours.items():
        theirs = O.interactions[pair].phys
        assert theirs.isOnJoint == (kinds[pair] == "joint") and theirs.kn == pytest.approx(phys.kn)
    with pytest.raises(ValueError, match="model = 'pfc'"):
        jcfpm.use("pfc")


def test_a_block_on_a_frictionless_joint_slides_at_g_sin_alpha_in_jcfpm(empty_scene):
    block, _ = block_on_slab(friction_deg=0)
    jcfpm.convert()
    tilt(26)
    assert acceleration(block) == pytest.approx(G * math.sin(math.radians(26)), rel=0.005)
