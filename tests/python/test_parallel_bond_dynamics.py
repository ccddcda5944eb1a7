"""Energy conservation, automatic time step, save/load and instability handling."""
import random

import pytest
from lattice import R, bonded_lattice, kinetic_energy, material
from yade import O

from toppling import scene


def shake(ids, speed=0.01, seed=1):
    rng = random.Random(seed)
    for i in ids:
        O.bodies[i].state.vel = (rng.uniform(-speed, speed), rng.uniform(-speed, speed), 0)
        O.bodies[i].state.angVel = (0, 0, rng.uniform(-speed, speed) / R)


def test_undamped_lattice_conserves_energy_with_auto_timestep(empty_scene):
    # Bonds 20x stiffer than contacts: a time step blind to bond stiffness would blow up.
    ids = bonded_lattice(8, 8, material(bondYoung=2e10), safety=0.5)
    shake(ids)
    law = scene.bond_law()
    bonds = law.countBonds(1)
    e0 = kinetic_energy() + law.elasticEnergy()
    drift = 0.0
    for _ in range(100):
        O.run(100, True)
        drift = max(drift, abs(kinetic_energy() + law.elasticEnergy() - e0) / e0)
    assert O.iter == 10_000
    assert law.countBonds(1) == bonds > 0 and not law.breakMode
    assert drift < 0.01


def test_save_load_continues_identically(empty_scene, tmp_path):
    mat = material(bondTensileStrength=2e4, bondCohesion=2e4)  # weak: bonds break under gravity
    ids = bonded_lattice(6, 10, mat, gravity=(0, -9.81e3, 0), fixed_bottom=True, local_damping=0.1)
    O.run(200, True)
    saved = str(tmp_path / "mid.yade.gz")
    O.save(saved)
    O.run(300, True)
    reference = [O.bodies[i].state.pos for i in ids]
    reference_breaks = list(scene.bond_law().breakTime)
    O.load(saved)
    O.run(300, True)
    assert [O.bodies[i].state.pos for i in ids] == reference
    assert list(scene.bond_law().breakTime) == reference_breaks


def test_unstable_run_stops_with_a_message(empty_scene):
    ids = bonded_lattice(4, 4, material(), timestepper=False)
    O.dt = 1e-3  # ~100x the critical time step
    shake(ids)
    O.run(5000, True)
    law = scene.bond_law()
    assert law.unstable
    assert O.iter < 5000
    assert all(abs(O.bodies[i].state.pos[0]) < 1e300 for i in ids)


@pytest.mark.parametrize("attribute, value, message", [
    ("young", -1.0, "> 0"),
    ("normalDamping", 1.0, "[0, 1)"),
    ("bondNormalDamping", -0.1, "[0, 1)"),
    ("frictionAngle", -0.1, "[0, pi/2)"),
    ("bondRadiusMultiplier", 0.0, "> 0"),
    ("bondTensileStrength", -5.0, ">= 0"),
    ("bondYoung", float("nan"), ">= 0"),
])
def test_bad_material_values_are_rejected(attribute, value, message):
    with pytest.raises(ValueError) as err:
        material(**{attribute: value})
    assert f"ParallelBondMat.{attribute}" in str(err.value) and message in str(err.value)
    mat = material()
    with pytest.raises(ValueError):
        setattr(mat, attribute, value)
