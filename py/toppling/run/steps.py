"""Running a scene in this thread, a given number of steps or seconds, stopped if it went unstable."""
from __future__ import annotations

from yade import O
from yade.wrapper import Law2_ScGeom_ParallelBondPhys_ParallelBond, Law2_ScGeom_SmoothJointPhys_SmoothJoint

from toppling.build.engines import functor


def run_steps(steps: int) -> None:
    """Run ``steps`` time steps (fewer if a law stops the run), in this thread.

    ``O.run(steps, True)`` runs them in YADE's worker thread and polls every 40 ms for the end:
    a run of a few dozen steps (a tilt increment, ~1 ms of work) took 40 ms of wall time.
    """
    O.stopAtIter = O.iter + steps
    while O.iter < O.stopAtIter:  # a law stopping the run sets O.stopAtIter to the next iteration
        O.step()


def run_checked(seconds: float, what: str = "the run") -> None:
    """Run ``seconds`` of simulated time (at least one step), then check_stable(what)."""
    run_steps(max(1, int(seconds / O.dt)))
    check_stable(what)


def check_stable(what: str = "the run") -> None:
    """Raise RuntimeError if a law stopped the run as unstable (a pair moved more than R/10 in
    one step or a force was not finite; the law printed which pair)."""
    for cls in (Law2_ScGeom_ParallelBondPhys_ParallelBond, Law2_ScGeom_SmoothJointPhys_SmoothJoint):
        if functor(cls).unstable:
            raise RuntimeError(f"{what} went unstable: lower the time-step safety (engines.engines(safety=...)) "
                               "or raise the damping")
