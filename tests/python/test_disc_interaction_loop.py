"""The disc path (DiscInteractionLoop) computes what YADE's generic InteractionLoop computes: a
jointed, bonded slope tilted at once to 40 deg, so that bonds break and joints slide, runs the
same on both, to the last bit (one thread)."""
from types import SimpleNamespace

import numpy as np
from yade import O
from yade.wrapper import SmoothJointPhys

from examples import params
from toppling.build import engines
from toppling.load import tilting
from toppling.models import tilting_table
from toppling.run.steps import run_steps

STEPS, EVERY = 3000, 100


def trajectory(fast: bool) -> tuple[list[np.ndarray], tuple]:
    O.loadTmp("disc path")
    engines.set_fast(fast)
    states = []
    for _ in range(STEPS // EVERY):
        run_steps(EVERY)
        states.append(np.array([tuple(b.state.pos) + tuple(b.state.ori) + tuple(b.state.angVel) for b in O.bodies]))
    law = engines.bond_law()
    slips = [i.phys.slip for i in O.interactions if i.isReal and isinstance(i.phys, SmoothJointPhys)]
    return states, (list(law.breakId1), list(law.breakId2), list(law.breakMode), list(law.breakTime), slips)


def test_the_disc_path_runs_a_breaking_jointed_slope_as_the_generic_loop_does(empty_scene):
    model = SimpleNamespace(**{**params.TILTING_TABLE_IDEAL, "rmin": 0.003, "rmax": 0.012})  # 649 discs
    tilting_table.from_params(model, params).build()
    tilting.set_tilt(40.0)  # at once: a dynamic load that breaks bonds and slides joints
    O.saveTmp("disc path")
    generic, generic_breaks = trajectory(fast=False)
    fast, fast_breaks = trajectory(fast=True)
    assert len(generic_breaks[0]) >= 10  # the test breaks bonds (20 here)
    assert max(generic_breaks[-1]) > 1e-4  # and slides joints (0.1 mm and more)
    assert all(np.array_equal(a, b) for a, b in zip(generic, fast))  # tolerance 0: the same arithmetic
    assert fast_breaks == generic_breaks  # the breaks and every joint's slip
