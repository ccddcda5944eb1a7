"""toppling.analyse.energy: a bonded block resting on a frictionless smooth joint under gravity
keeps its mechanical energy without damping (springs, joints and gravity all counted); friction
(slip where the joint opens) and dashpots only take energy away."""
import pytest
from yade import O

from conftest import ROCK
from toppling.analyse import energy
from toppling.models import incline
from toppling.run.steps import run_steps


def energies(damping: float, bond_damping: float, friction_deg: float) -> list[float]:
    """The block dropped onto its joint as built (gravity on, nothing loaded): the energy every 100 steps."""
    rock = {**ROCK, "normalDamping": damping, "bondNormalDamping": bond_damping}
    incline.build(0.1, 0.05, 0.012 / 2.5, 0.012, rock, joint_friction_deg=friction_deg)
    found = [energy.mechanical()]
    for _ in range(30):
        run_steps(99)
        found.append(energy.mechanical())
    return found


def test_without_damping_the_block_keeps_its_energy_as_it_rings_on_its_joint(empty_scene):
    found = energies(0.0, 0.0, friction_deg=0.0)
    stored = energy.elastic()
    assert stored > 0  # it rings: the springs hold energy that came from gravity
    assert max(abs(e - found[0]) for e in found) < 1e-3 * stored


@pytest.mark.parametrize("damping", [0.0, 0.13])
def test_friction_and_dashpots_only_take_energy_away(empty_scene, damping):
    found = energies(damping, 1.5 * damping, friction_deg=45.0)
    rises = [later - earlier for earlier, later in zip(found, found[1:])]
    assert found[-1] < found[0] and max(rises) <= 1e-9 * abs(found[0] - found[-1])
