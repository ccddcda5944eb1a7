"""Tilting by rotating gravity (thesis Fig 5-7), in stages run to equilibrium or failure."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Optional, Sequence

import numpy as np
from yade import O

from toppling.build.engines import G, newton
from toppling.run.steps import check_stable, run_checked, run_steps, steps_in
from toppling.checks import require


def set_tilt(alpha_deg: float) -> None:
    """Tilt the table by ``alpha_deg`` towards +x (the toe side): gravity (g sin a, -g cos a)."""
    require("tilt", alpha_deg, "[0, 90)")
    a = math.radians(alpha_deg)
    newton().gravity = (G * math.sin(a), -G * math.cos(a), 0)


def current_tilt() -> float:
    """The tilt [deg] that the scene's gravity stands for (inverse of set_tilt)."""
    gx, gy = tuple(newton().gravity)[:2]
    return math.degrees(math.atan2(gx, -gy))


def positions(ids: Sequence[int]) -> np.ndarray:
    return np.array([tuple(O.bodies[i].state.pos)[:2] for i in ids])


def kinetic_energy_above(ids: Sequence[int], floor: float) -> float:
    """Kinetic energy [J] (translation and rotation) of the discs ``ids`` whose centre is above
    height ``floor``. A column that toppled off the table's edge falls on into the void, and its
    energy, growing with the square of time, would soon hide the slope's own."""
    total = 0.0
    for i in ids:
        s = O.bodies[i].state
        if s.pos[1] > floor:
            total += 0.5 * s.mass * s.vel.squaredNorm() + 0.5 * sum(s.inertia[k] * s.angVel[k] ** 2 for k in range(3))
    return total


@dataclass
class StageCriteria:
    chunk: float = 0.02  # simulated seconds between checks
    rest_speed: float = 1e-3  # [m/s] every watched group's median slower than this: equilibrium
    fail_displacement: float = 5e-3  # [m] a watched group's median moved more since the last equilibrium: gone
    # [s] still moving faster than rest_speed after this, and moved further than rest_speed times
    # the stage's time: failed (creep); a group that moved less is ringing in place (no local damping)
    max_stage_time: float = 0.4
    # how many watched groups must pass fail_displacement for the stage to fail; fewer are gone
    # (a toe column toppled off the table on its own) and no longer judged for rest
    fail_columns: int = 1
    # [s] rest is judged on the medians' speed over this window (0: one chunk): without local
    # damping a standing slope rings, and over one chunk a median's speed is the ringing's
    rest_window: float = 0.0

    def __post_init__(self):
        for name in ("chunk", "rest_speed", "fail_displacement", "max_stage_time"):
            require(name, getattr(self, name), "(0, inf)")
        require("fail_columns", self.fail_columns, "[1, inf)")
        if self.fail_columns != int(self.fail_columns):
            raise ValueError(f"fail_columns = {self.fail_columns} is invalid: it must be a whole number >= 1")
        require("rest_window", self.rest_window, "[0, inf)")
        if 0 < self.rest_window < self.chunk:
            raise ValueError(f"rest_window = {self.rest_window} is invalid: it must be 0 (one chunk) or >= chunk "
                             f"= {self.chunk}")

    @property
    def window_chunks(self) -> int:
        """The chunks in rest_window (at least one)."""
        return max(1, round(self.rest_window / self.chunk))

    def collapsed(self, off: np.ndarray) -> bool:
        """Whether enough watched groups are ``off`` (gone) for the stage to fail by fail_displacement:
        ``fail_columns`` of them, or all if fewer are left (the others toppled off alone earlier)."""
        return int(np.sum(off)) >= min(self.fail_columns, len(off))


def gone(now: np.ndarray, reference: np.ndarray, criteria: StageCriteria) -> np.ndarray:
    """Which watched groups (medians ``now``) moved more than fail_displacement from ``reference``."""
    return np.linalg.norm(now - reference, axis=1) > criteria.fail_displacement


def ramp(from_deg: float, to_deg: float, duration: float, on_chunk: Optional[Callable[[], None]] = None,
         update: float = 1e-3, start: Optional[float] = None) -> None:
    """Turn gravity from ``from_deg`` to ``to_deg`` linearly over ``duration`` simulated seconds,
    in increments every ``update`` seconds: a large tilt applied at once would overshoot its
    static response (up to twice the stress, a dynamic load) and break bonds a slowly tilted
    table never breaks. ``on_chunk`` is called about every 0.02 s. ``start``: the simulated time
    the ramp began (now by default; a resumed run passes the checkpointed one). A ramp to the
    tilt it starts from has nothing to do, whatever its duration."""
    if from_deg == to_deg:
        set_tilt(to_deg)
        return
    require("duration", duration, "(0, inf)")
    require("update", update, "(0, inf)")
    start, last_report = O.time if start is None else start, O.time
    while O.time - start < duration:
        set_tilt(from_deg + (to_deg - from_deg) * (O.time - start) / duration)
        run_steps(steps_in(update))  # of the current time step: a resumed ramp makes the same increments
        check_stable(f"the tilt from {from_deg} to {to_deg} deg")
        if on_chunk and O.time - last_report >= 0.02:
            on_chunk()
            last_report = O.time
    set_tilt(to_deg)


def medians(groups: Sequence[Sequence[int]]) -> np.ndarray:
    """Median position (x and y apart) of each group of discs: where most of the group is. A part
    that breaks off and falls away does not move it, where it drags a mean along: five of a
    column top's seventeen discs falling off the table moved the top's mean 56 mm while the rest
    stood, as if the column had toppled off (docs/tilting_table.md, "A column top's corner
    falling off")."""
    return np.array([np.median(positions(group), axis=0) for group in groups])


def stage_outcome(now: np.ndarray, before: Optional[np.ndarray], reference: np.ndarray, elapsed: float,
                  criteria: StageCriteria) -> Optional[str]:
    """The stage's outcome from the watched groups' medians ``now``, ``window_chunks`` chunks ago
    (``before``; None while the stage is younger) and at the stage's start (``reference``),
    ``elapsed`` seconds into it; None while it is undecided.
    At the time limit a group still moving but whose mean speed over the stage is below
    rest_speed vibrates in place (without local damping a column can ring for seconds): that is
    equilibrium, not creep."""
    off = gone(now, reference, criteria)
    if criteria.collapsed(off):
        return "failed"
    window = criteria.window_chunks * criteria.chunk
    speed = np.inf if before is None else np.linalg.norm(now - before, axis=1)[~off].max(initial=0.0) / window
    if speed < criteria.rest_speed:
        return "equilibrium"
    if elapsed > criteria.max_stage_time:
        drift = np.linalg.norm(now - reference, axis=1)[~off].max(initial=0.0) / elapsed
        return "failed" if drift >= criteria.rest_speed else "equilibrium"
    return None


class Watch:
    """The medians of watched groups of discs, kept over the last ``rest_window`` of chunks in
    ``history`` (a list of lists: a run that keeps it in its checkpoint resumes a stage judged
    as the uninterrupted stage is, rather than waiting a whole rest window again)."""

    def __init__(self, groups: Sequence[Sequence[int]], criteria: StageCriteria, history: Optional[list] = None):
        self.groups = groups
        self.length = criteria.window_chunks + 1
        self.history = [] if history is None else history
        if not self.history:
            self.history.append(medians(groups).tolist())

    def chunk_done(self) -> tuple[np.ndarray, Optional[np.ndarray]]:
        """The medians now and a rest window ago (None until the watch is that old)."""
        self.history.append(medians(self.groups).tolist())
        del self.history[:-self.length]
        full = len(self.history) == self.length
        return np.array(self.history[-1]), np.array(self.history[0]) if full else None


def on_table(groups: Sequence[Sequence[int]], floor: float) -> list[list[int]]:
    """Each group's discs whose centre is above height ``floor`` (empty for a group that has left
    the table: it falls on into the void and would never come to rest)."""
    return [[i for i in group if O.bodies[i].state.pos[1] > floor] for group in groups]


def fastest_speed(groups: Sequence[Sequence[int]], chunk: float, on_chunk: Optional[Callable[[], None]] = None) -> float:
    """Run ``chunk`` simulated seconds and return the speed [m/s] of the fastest median of the
    non-empty ``groups`` over it (0 if none is left)."""
    groups = [group for group in groups if group]
    before = medians(groups).reshape(-1, 2)
    run_checked(chunk, "the run after a failure")
    if on_chunk:
        on_chunk()
    return float(np.linalg.norm(medians(groups).reshape(-1, 2) - before, axis=1).max(initial=0.0)) / chunk


def run_arrest(watched: Sequence[Sequence[int]], floor: float, criteria: StageCriteria, arrest_time: float,
               on_chunk: Optional[Callable[[], None]] = None, start: Optional[float] = None) -> Optional[float]:
    """After a failing stage, run on at the same tilt until what is left of the ``watched``
    groups on the table (above ``floor``) comes to rest, the fastest median slower than
    rest_speed: the failure came to rest; return how long after ``start`` (the
    failure; now by default) that took. None if the slope still moves ``arrest_time`` seconds
    after the failure: it collapses. The parts still on the table are taken anew every chunk,
    so a piece is judged until it drops below ``floor``."""
    require("arrest_time", arrest_time, "(0, inf)")
    start = O.time if start is None else start
    while O.time - start < arrest_time:
        if fastest_speed(on_table(watched, floor), criteria.chunk, on_chunk) < criteria.rest_speed:
            return O.time - start
    return None


def run_stage(alpha_deg: float, watched: Sequence[Sequence[int]], reference: np.ndarray, criteria: StageCriteria,
              on_chunk: Optional[Callable[[], None]] = None, start: Optional[float] = None,
              history: Optional[list] = None) -> str:
    """Tilt to ``alpha_deg`` and run until ``'equilibrium'`` or ``'failed'`` (see
    StageCriteria), judged on the medians of the ``watched`` groups of discs (one loose disc
    rattling, or a corner breaking off, must not count as a column moving) against their
    ``reference`` positions: failed when ``fail_columns`` groups have moved more than
    ``fail_displacement``, or when the others still move faster than ``rest_speed`` after
    ``max_stage_time`` and have moved further than ``rest_speed`` times the stage's time
    (stage_outcome).
    ``start``: the simulated time the stage began (now by default; a resumed run passes the
    checkpointed one, so max_stage_time counts the whole stage); ``history``: the Watch's, kept
    by the caller (a resumed run passes the checkpointed one)."""
    set_tilt(alpha_deg)
    start, watch = O.time if start is None else start, Watch(watched, criteria, history)
    while True:
        run_checked(criteria.chunk, f"the stage at {alpha_deg} deg")
        now, before = watch.chunk_done()
        outcome = stage_outcome(now, before, reference, O.time - start, criteria)
        if on_chunk:
            on_chunk()
        if outcome:
            return outcome
