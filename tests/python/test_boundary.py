"""Boundary discs flagged near segments, fixed or driven."""
import pytest
from lattice import R, bonded_lattice, material
from yade import O

from toppling.build import boundary
from toppling.run.steps import run_steps


def test_discs_near_the_base_are_flagged_and_held(empty_scene):
    ids = bonded_lattice(6, 6, material(), gravity=(0, -9.81e3, 0))
    base = boundary.near([((-R, 0), (12 * R, 0))], distance=R)
    assert sorted(base) == ids[:6]  # the bottom row, centres on y = 0
    boundary.fix(base, "xy")
    start = [O.bodies[i].state.pos for i in base]
    run_steps(500)
    assert [O.bodies[i].state.pos for i in base] == start
    assert max(abs(O.bodies[i].state.displ()[1]) for i in ids[6:]) > 0  # the rest is free


def test_platen_moves_at_its_velocity(empty_scene):
    bonded_lattice(4, 4, material())
    top = boundary.near([((-R, 6 * R), (10 * R, 6 * R))], distance=R)
    boundary.move(top, (0, -0.01))
    y0 = [O.bodies[i].state.pos[1] for i in top]
    run_steps(100)
    assert [O.bodies[i].state.pos[1] - y for i, y in zip(top, y0)] == pytest.approx([-0.01 * O.time] * len(top), rel=1e-9)


def test_bad_boundary_input_is_rejected(empty_scene):
    with pytest.raises(ValueError, match="dofs"):
        boundary.fix([], "z")
    with pytest.raises(ValueError, match="distance"):
        boundary.near([((0, 0), (1, 0))], -1.0)
