"""Energy conservation, automatic time step, save/load and instability handling."""
import math
import random

import pytest
from lattice import R, bonded_lattice, material
from yade import O

from toppling.analyse import energy
from toppling.build import bonding, boundary, engines, packing
from toppling.build.discs import add_discs
from toppling.run import tilt_run
from toppling.run.steps import run_steps


def shake(ids, speed=0.01, seed=1):
    rng = random.Random(seed)
    for i in ids:
        O.bodies[i].state.vel = (rng.uniform(-speed, speed), rng.uniform(-speed, speed), 0)
        O.bodies[i].state.angVel = (0, 0, rng.uniform(-speed, speed) / R)


@pytest.mark.parametrize("gap, safety, tolerance", [
    # Bonds only (discs 1 % apart): a linear system, whose leapfrog energy is conserved exactly
    # but for geometric nonlinearity; measured drift ~1e-6.
    (0.02 * R, 0.5, 1e-3),
    # YADE's default safety, which the tilting-table runs may use (timestep_safety 0.8).
    (0.02 * R, 0.8, 1e-3),
    # Touching discs: contacts switching on and off within a step cost O(dt) energy.
    (0.0, 0.3, 0.01),
])
def test_undamped_lattice_conserves_energy_with_auto_timestep(empty_scene, gap, safety, tolerance):
    # Bonds 20x stiffer than contacts: a time step blind to bond stiffness would blow up.
    # Frictionless contacts: Coulomb slip at touching, barely loaded contacts would dissipate.
    ids = bonded_lattice(8, 8, material(bondYoung=2e10, frictionAngle=0.0), gap=gap, safety=safety)
    shake(ids)
    law = engines.bond_law()
    bonds = law.countBonds(1)
    e0 = energy.mechanical()
    drift = 0.0
    for _ in range(100):
        run_steps(99)
        drift = max(drift, abs(energy.mechanical() - e0) / e0)
    assert O.iter == 10_001
    assert law.countBonds(1) == bonds > 100 and not law.breakMode
    assert drift < tolerance


@pytest.mark.parametrize("timestepper", [False, True])
def test_save_load_continues_identically(empty_scene, tmp_path, timestepper):
    mat = material(bondTensileStrength=2e4, bondCohesion=2e4)  # weak: bonds break under gravity
    ids = bonded_lattice(6, 10, mat, gravity=(0, -9.81e3, 0), fixed_bottom=True, local_damping=0.1,
                         timestepper=timestepper)
    if not timestepper:
        O.dt = 2e-7
    run_steps(200)
    saved = str(tmp_path / "mid.yade.gz")
    O.save(saved)
    run_steps(300)
    reference = [O.bodies[i].state.pos for i in ids]
    reference_breaks = list(engines.bond_law().breakTime)
    O.load(saved)
    run_steps(300)
    assert len(reference_breaks) > 20
    if timestepper:
        # YADE's collider rebuilds its interaction order after O.load, so new contacts are summed
        # in another order: equal to round-off, not bitwise (also so with YADE's own laws).
        assert max((O.bodies[i].state.pos - r).norm() for i, r in zip(ids, reference)) < 1e-12 * R
        assert len(engines.bond_law().breakTime) == len(reference_breaks)
    else:
        assert [O.bodies[i].state.pos for i in ids] == reference
        assert list(engines.bond_law().breakTime) == reference_breaks


def test_unstable_run_stops_with_a_message(empty_scene):
    ids = bonded_lattice(4, 4, material(), timestepper=False)
    O.dt = 1e-3  # ~100x the critical time step
    shake(ids)
    run_steps(5000)
    law = engines.bond_law()
    assert law.unstable
    assert O.iter < 50
    assert all(abs(O.bodies[i].state.pos[0]) < 1.0 for i in ids)  # stopped before flying apart


BAD_VALUES = [
    ("young", -1.0, "> 0"),
    ("frictionAngle", -0.1, "[0, pi/2)"),
    ("normalDamping", 1.0, "[0, 1)"),
    ("bondNormalDamping", -0.1, "[0, 1)"),
    ("bondRadiusMultiplier", 0.0, "> 0"),
    ("bondTensileStrength", -5.0, ">= 0"),
    ("bondYoung", float("nan"), ">= 0"),
]


@pytest.mark.parametrize("attribute, value, message", BAD_VALUES)
def test_bad_material_values_are_rejected(attribute, value, message):
    with pytest.raises(ValueError) as err:
        material(**{attribute: value})
    assert f"ParallelBondMat.{attribute}" in str(err.value) and message in str(err.value)


@pytest.mark.parametrize("attribute, value, message", BAD_VALUES[2:])
def test_bad_values_set_later_are_rejected(attribute, value, message):
    with pytest.raises(ValueError, match=attribute):
        setattr(material(), attribute, value)


@pytest.mark.parametrize("attribute, value, message", BAD_VALUES[:2])
def test_bad_inherited_values_set_later_stop_the_run(empty_scene, attribute, value, message):
    mat = material()
    bonded_lattice(2, 2, mat, timestepper=False)
    setattr(mat, attribute, value)  # YADE's own setter for ElastMat/FrictMat attributes
    O.interactions.clear()
    O.dt = 1e-7
    run_steps(100)
    assert O.iter < 100


def test_bonding_after_settling_is_stress_free_and_limits_the_time_step(empty_scene):
    # Thesis §3.2: discs settle under gravity first, then the bonds are installed.
    mat = material(bondYoung=2e10)
    bonded_lattice(6, 6, mat, gravity=(0, -9.81, 0), fixed_bottom=True, local_damping=0.5)
    law = engines.bond_law()
    for i in list(O.interactions):  # start unbonded: remove the lattice's bonds
        O.interactions.erase(i.id1, i.id2)
    run_steps(500)
    dt_before = O.dt
    bonds = bonding.bond_within_gap(1e-6 * R)
    assert bonds == law.countBonds(1) > 50
    assert sum(bonding.intact_bonds(b.id) for b in O.bodies) == 2 * bonds
    assert all(i.phys.bondNormalForce == 0 and i.phys.bondMoment == 0 for i in O.interactions if i.phys.bondState == 1)
    assert O.dt <= 0.5 * law.criticalTimeStep() * (1 + 1e-12) < dt_before  # bonds 20x stiffer than contacts
    run_steps(2000)
    assert not law.unstable and not law.breakMode


def test_rock_is_the_discs_held_by_two_bonds_not_a_loose_pair(empty_scene):
    """A chain of four bonded discs beside a bonded pair: the pair and the chain's ends are not rock."""
    mat = material()
    ids = add_discs([(2 * R * k, 0.0, R) for k in range(4)] + [(2 * R * k, 10 * R, R) for k in range(2)], mat)
    O.engines = engines.engines()
    O.step()
    assert bonding.bond_within_gap(1e-6 * R, ids) == 3 + 1
    assert bonding.rock(ids) == ids[1:3]
    assert bonding.rock(ids, min_bonds=1) == ids


def test_breaks_that_free_a_loose_disc_are_told_from_cracks_in_the_rock(empty_scene):
    """A chain of four discs, the middle two fixed, with a knob disc bonded on top of them, a
    bonded pair, and two bonded triangles tied by one bond, the first fixed. Pulled off, the
    chain's ends, the pair and the knob (both its bonds) free a disc: debris, also the knob's first
    break, of discs each held by two bonds. Pulling the second triangle off cracks the rock: its
    discs and the first's each keep two bonds."""
    mat = material(bondTensileStrength=1e3, bondCohesion=1e3)
    chain = [(2 * R * k, 0.0, R) for k in range(4)]
    h = math.sqrt(3) * R
    triangles = [(0.0, 20 * R, R), (-2 * R, 20 * R, R), (-R, 20 * R - h, R),
                 (2 * R, 20 * R, R), (4 * R, 20 * R, R), (3 * R, 20 * R + h, R)]
    ids = add_discs(chain + [(3 * R, h, R), (0.0, 10 * R, R), (2 * R, 10 * R, R)] + triangles, mat)
    end0, fixed1, fixed2, end3, knob, pair_a, pair_b = ids[:7]
    for i in (fixed1, fixed2, *ids[7:10]):
        O.bodies[i].state.blockedDOFs = "xyzXYZ"
    O.engines = engines.engines(gravity=(0, 0, 0))
    O.step()
    assert bonding.bond_within_gap(1e-6 * R, ids) == 3 + 2 + 1 + 3 + 3 + 1
    for disc, direction in ((end0, (-1, 0)), (end3, (1, 0)), (knob, (0, 1)), (pair_a, (-1, 0)), (pair_b, (1, 0))):
        boundary.move([disc], (0.01 * direction[0], 0.01 * direction[1], 0))
    boundary.move(ids[10:], (0.01, 0, 0))
    law = engines.bond_law()
    while len(law.breakMode) < 6 and O.iter < 100000:  # all but the fixed discs' bonds and the triangles' own
        run_steps(100)
    assert len(law.breakMode) == 6
    tie = [n for n, pair in enumerate(zip(law.breakId1, law.breakId2)) if set(pair) == {ids[7], ids[10]}]
    assert bonding.rock_breaks(0, 6) == tie
    sorted_breaks = tilt_run.sort_breaks_before_stages({"level": 6, "ramp": 0}, lambda t: 0.0)
    assert sorted_breaks == {"level": 6, "ramp": 0, "loose": {"level": 5, "ramp": 0}}


@pytest.mark.parametrize("shrink", [False, True])
def test_a_bond_installed_over_an_overlap_takes_the_contact_force_in_tension(empty_scene, shrink):
    """Two discs overlapping by u, bonded stress-free: at rest the bond holds the contact spring
    apart, tension kc kb u / (kc + kb) (springs in parallel); shrink_overlaps removes it."""
    u = 0.01 * R
    discs = [(0.0, 0.0, R), (2 * R - u, 0.0, R)]
    if shrink:
        discs = packing.shrink_overlaps(discs)
    ids = add_discs(discs, material())
    O.bodies[ids[0]].state.blockedDOFs = "xyzXYZ"
    O.bodies[ids[1]].state.blockedDOFs = "yzXYZ"
    O.engines = engines.engines(gravity=(0, 0, 0), local_damping=0.7)
    O.step()
    assert bonding.bond_within_gap(1e-6 * R, ids) == 1
    run_steps(3000)
    phys = O.interactions[ids[0], ids[1]].phys
    kb = phys.bondKn * phys.bondArea
    expected = 0.0 if shrink else -phys.contactKn * kb * u / (phys.contactKn + kb)
    assert phys.bondNormalForce == pytest.approx(expected, rel=1e-3, abs=1e-9 * kb * u)
    assert abs(O.bodies[ids[1]].state.vel[0]) < 1e-9


def test_set_local_damping_changes_the_integrators_damping(empty_scene):
    """A free disc falling from rest under local damping d accelerates at g (1 - d) (YADE's
    local damping takes d |F| against the velocity): v = g (1 - d) t after the change."""
    (disc,) = add_discs([(0.0, 0.0, R)], material())
    O.engines = engines.engines(gravity=(0, -9.81, 0), local_damping=0.7, timestepper=False)
    O.dt = 1e-4
    engines.set_local_damping(0.25)
    run_steps(1000)
    assert O.bodies[disc].state.vel[1] == pytest.approx(-9.81 * 0.75 * O.time, rel=1e-3)
    with pytest.raises(ValueError, match=r"local_damping = 1.0 is invalid: it must be in \[0, 1\)"):
        engines.set_local_damping(1.0)
