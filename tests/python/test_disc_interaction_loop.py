"""The disc path (DiscInteractionLoop) computes what YADE's generic InteractionLoop computes: a
jointed, bonded slope tilted at once to 40 deg, so that bonds break and joints slide, runs the
same on both, to the last bit (one thread; the discs' orientations to round-off); what is read of its bonds during and after a run
(its bonds then held in an array) is what the generic loop's objects hold."""
from types import SimpleNamespace

import numpy as np
import pytest
from yade import O
from yade.wrapper import (DiscInteractionLoop, DiscNewtonIntegrator, InsertionSortCollider, ParallelBondPhys, PyRunner,
                          SmoothJointPhys)

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
        states.append((np.array([tuple(b.state.pos) + tuple(b.state.angVel) for b in O.bodies]),
                       np.array([tuple(b.state.ori) for b in O.bodies])))
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
    assert all(np.array_equal(a[0], b[0]) for a, b in zip(generic, fast))  # tolerance 0: the same arithmetic
    # orientations: a disc's turns about z applied at once, not step by step (DiscNewtonIntegrator)
    worst = max(np.abs(a[1] - b[1]).max() for a, b in zip(generic, fast))
    print(f"largest difference in an orientation's quaternion components: {worst:.1e}")
    assert worst < 1e-13
    assert fast_breaks == generic_breaks  # the breaks and every joint's slip


BOND_STATE = ("normalForce", "shearForce", "contactNormalForce", "contactShearForce", "isSlipping", "bondState",
              "bondNormalForce", "bondShearForce", "bondMoment", "bondSigmaMax", "bondTauMax", "normalBefore", "kn", "ks")


def bond_objects() -> list:
    """Every rock pair's physics and geometry, as Python reads them."""
    return [(i.id1, i.id2, tuple(getattr(i.phys, name) for name in BOND_STATE),
             (i.geom.penetrationDepth, tuple(i.geom.normal), tuple(i.geom.contactPoint)))
            for i in O.interactions if i.isReal and isinstance(i.phys, ParallelBondPhys)]


def observed(fast: bool) -> tuple[list, list]:
    """What a periodic engine reads of the bonds during 1000 steps, and the bonds' objects after."""
    O.loadTmp("disc path")
    engines.set_fast(fast)
    seen = []
    O.engines = O.engines + [PyRunner(iterPeriod=37, command="seen.append((O.iter, bond_objects()))")]
    yade_globals = __import__("builtins")
    yade_globals.seen, yade_globals.bond_objects = seen, bond_objects  # PyRunner's commands run in __main__/builtins
    run_steps(1000)
    return seen, bond_objects()


def test_whoever_reads_the_bonds_during_and_after_a_run_reads_what_the_generic_loop_holds(empty_scene):
    model = SimpleNamespace(**{**params.TILTING_TABLE_IDEAL, "rmin": 0.003, "rmax": 0.012})
    tilting_table.from_params(model, params).build()
    tilting.set_tilt(40.0)
    O.saveTmp("disc path")
    generic_seen, generic_after = observed(fast=False)
    fast_seen, fast_after = observed(fast=True)
    assert len(fast_seen) == 1000 // 37 and fast_seen == generic_seen  # a periodic engine: the array was flushed for it
    assert len(fast_after) > 1000 and fast_after == generic_after  # after run_steps: every bond's state and geometry


def test_run_steps_refuses_a_negative_count(empty_scene):
    model = SimpleNamespace(**{**params.TILTING_TABLE_IDEAL, "rmin": 0.003, "rmax": 0.012})
    tilting_table.from_params(model, params).build()
    loop = next(e for e in O.engines if isinstance(e, DiscInteractionLoop))
    with pytest.raises(ValueError, match="steps = -1: give 0 or more"):
        loop.runSteps(-1)


def test_switching_paths_leaves_the_collider_asking_the_integrator_that_runs(empty_scene):
    model = SimpleNamespace(**{**params.TILTING_TABLE_IDEAL, "rmin": 0.003, "rmax": 0.012})
    tilting_table.from_params(model, params).build()
    run_steps(10)  # the collider has found its integrator (and a loaded scene keeps it)
    for fast in (False, True):
        engines.set_fast(fast)
        collider = next(e for e in O.engines if isinstance(e, InsertionSortCollider))
        assert collider.newton is engines.newton()
        assert isinstance(engines.newton(), DiscNewtonIntegrator) == fast
