"""A progress line on the console for long runs."""
from __future__ import annotations

import time
from typing import Callable, Optional

from yade import O, utils

from toppling.build.engines import broken_bonds


class Progress:
    """Prints ``label, step, simulated time, kinetic energy, broken bonds, ETA`` at most every
    ``every`` wall seconds. ETA from the fraction of the work done that the caller passes, at the
    rate since the first fraction this process saw (a resumed run has done part of the work in
    an earlier process: that part took none of this one's time), or from the simulated time
    still to run at the simulated-time rate since the last line (a phase of known length, such
    as a post-failure run). ``energy`` gives the kinetic energy to print (by default the whole
    scene's)."""

    def __init__(self, every: float = 10.0, energy: Callable[[], float] = utils.kineticEnergy):
        self.every, self.energy = every, energy
        self.start = time.time()
        self.last = -float("inf")
        self.last_sim_time = None
        self.first_fraction: Optional[tuple[float, float]] = None  # (wall time, fraction done)

    def __call__(self, label: str, fraction_done: Optional[float] = None, force: bool = False,
                 remaining_time: Optional[float] = None, stage_bound: Optional[float] = None) -> None:
        """``stage_bound``: simulated seconds within which the current stage ends at the latest
        (its time limit), printed as wall time beside an ETA that cannot see the stage's end."""
        now = time.time()
        if not force and now - self.last < self.every:
            return
        elapsed = now - self.start
        wall_per_sim = None  # at the simulated-time rate since the last line
        if self.last_sim_time is not None and O.time > self.last_sim_time:
            wall_per_sim = (now - self.last) / (O.time - self.last_sim_time)
        eta = "?"
        if remaining_time is not None and wall_per_sim is not None:
            eta = f"{remaining_time * wall_per_sim:.0f} s"
        elif fraction_done is not None:
            if self.first_fraction is None:
                self.first_fraction = (now, fraction_done)
            since, done_before = self.first_fraction
            if fraction_done > done_before:
                eta = f"{(now - since) * (1 - fraction_done) / (fraction_done - done_before):.0f} s"
        if stage_bound is not None and wall_per_sim is not None:
            eta += f" (this stage ends within {stage_bound * wall_per_sim:.0f} s)"
        self.last, self.last_sim_time = now, O.time
        print(f"[{elapsed:7.0f} s] {label}  step {O.iter}  t = {O.time:.4f} s  "
              f"Ek = {self.energy():.3e} J  broken bonds {broken_bonds()}  ETA {eta}",
              flush=True)

    @property
    def wall_time(self) -> float:
        return time.time() - self.start
