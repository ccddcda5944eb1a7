"""Running a scene in this thread, a given number of steps or seconds, stopped if it went unstable."""
from __future__ import annotations

from yade import O
from yade.wrapper import DiscInteractionLoop, Law2_ScGeom_ParallelBondPhys_ParallelBond, Law2_ScGeom_SmoothJointPhys_SmoothJoint

from toppling.build.engines import functor
from toppling.checks import require


def run_steps(steps: int) -> None:
    """Run ``steps`` time steps (fewer if a law stops the run), in this thread.

    ``O.run(steps, True)`` runs them in YADE's worker thread and polls every 40 ms for the end:
    a run of a few dozen steps (a tilt increment, ~1 ms of work) took 40 ms of wall time. On the
    disc path the steps run in C++ (``DiscInteractionLoop.runSteps``), the bonds in an array.
    """
    require("steps", steps, "[0, inf)")
    loop = next((e for e in O.engines if isinstance(e, DiscInteractionLoop)), None)
    if loop is not None:
        loop.runSteps(steps)
        return
    O.stopAtIter = O.iter + steps
    while O.iter < O.stopAtIter:  # a law stopping the run sets O.stopAtIter to the next iteration
        O.step()


def steps_in(seconds: float) -> int:
    """The number of time steps (at least one) in ``seconds`` of simulated time."""
    require("seconds", seconds, "(0, inf)")
    if not 0 < O.dt < float("inf"):  # a loop waiting for simulated time would wait for ever
        raise RuntimeError(f"O.dt = {O.dt}: the time step must be > 0 s; is there a stiffness (a contact, a bond) for "
                           "the time stepper to work from, or did the run go unstable?")
    return max(1, int(seconds / O.dt))


def run_checked(seconds: float, what: str = "the run") -> None:
    """Run ``seconds`` of simulated time (at least one step), then check_stable(what)."""
    run_steps(steps_in(seconds))
    check_stable(what)


def check_stable(what: str = "the run") -> None:
    """Raise RuntimeError if a law stopped the run as unstable (a pair moved more than R/10 in
    one step or a force was not finite; the law printed which pair)."""
    for cls in (Law2_ScGeom_ParallelBondPhys_ParallelBond, Law2_ScGeom_SmoothJointPhys_SmoothJoint):
        try:
            law = functor(cls)
        except LookupError:  # a scene of another model (JCFpm) has no such check
            continue
        if law.unstable:
            raise RuntimeError(f"{what} went unstable: lower the time-step safety (engines.engines(safety=...)); "
                               "damping does not help: dashpots lower the stable step (docs/performance.md)")
