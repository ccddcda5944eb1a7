"""Long runs: a progress line on the console, checkpoints that resume, monitoring points."""
from __future__ import annotations

import json
import math
import os
import time
from typing import Any, Callable, Optional, Sequence

from yade import O, utils

from toppling import analysis, columns, scene


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
              f"Ek = {self.energy():.3e} J  broken bonds {scene.broken_bonds()}  ETA {eta}",
              flush=True)

    @property
    def wall_time(self) -> float:
        return time.time() - self.start


class Checkpoint:
    """``<folder>/checkpoint.yade.bz2`` (the scene, by ``O.save``) + ``checkpoint.json`` (the
    driver's own state: where in its loop it was)."""

    def __init__(self, folder: str):
        os.makedirs(folder, exist_ok=True)
        self.scene_path = os.path.join(folder, "checkpoint.yade.bz2")
        self.state_path = os.path.join(folder, "checkpoint.json")

    def exists(self) -> bool:
        return os.path.exists(self.scene_path) and os.path.exists(self.state_path)

    def save(self, state: dict[str, Any]) -> None:
        # Both written aside and then moved into place: a run killed while saving (a long run is
        # stopped at any moment) leaves the previous checkpoint whole.
        scene_tmp = self.scene_path.replace("checkpoint.", "checkpoint.saving.")
        O.save(scene_tmp)
        state_tmp = self.state_path + ".tmp"
        with open(state_tmp, "w") as f:
            json.dump(state, f)
        os.replace(scene_tmp, self.scene_path)
        os.replace(state_tmp, self.state_path)

    def continues(self, inputs: dict[str, Any], resume: int, free: Sequence[str] = (),
                  added: Optional[dict[str, Any]] = None) -> bool:
        """Whether a run with parameters ``inputs`` continues this checkpoint rather than starting
        afresh: ``resume`` = 1 yes, 0 no, -1 if there is one, so that running the same command
        again continues a stopped run. With -1 the checkpoint's ``"inputs"`` must be the same
        (apart from the ``free`` ones, which may change between a run and its continuation):
        a run with other parameters stops rather than overwrite another run's results. ``added``
        names parameters newer than older checkpoints, with the value those runs had."""
        if resume not in (-1, 0, 1):
            raise ValueError(f"resume = {resume} is invalid: it must be -1 (continue a run with the same "
                             "parameters), 0 (start afresh) or 1 (continue the checkpoint)")
        if resume != -1:
            return bool(resume)
        if not self.exists():
            return False
        with open(self.state_path) as f:
            saved = {**(added or {}), **json.load(f).get("inputs", {})}

        def fixed(d: dict[str, Any]) -> dict[str, Any]:
            return {k: v for k, v in json.loads(json.dumps(d)).items() if k not in free}  # as stored

        then, now = fixed(saved), fixed(inputs)
        differ = sorted(k for k in then.keys() | now.keys() if then.get(k) != now.get(k))
        if differ:
            changes = ", ".join(f"{k} {then.get(k)!r} there, {now.get(k)!r} here" for k in differ)
            raise ValueError(f"{os.path.dirname(self.state_path)} holds the checkpoint of a run with other "
                             f"parameters ({changes}): resume=0 starts afresh and discards it, resume=1 "
                             "continues it with these parameters, or choose another out folder")
        return True

    def load(self) -> dict[str, Any]:
        if not self.exists():
            raise FileNotFoundError(f"no checkpoint in {os.path.dirname(self.scene_path)}: run without resume first")
        O.load(self.scene_path)
        with open(self.state_path) as f:
            return json.load(f)


class MonitoringPoints:
    """Displacement histories (X, Y, total) of labelled discs, e.g. column tops ``G-7``."""

    def __init__(self, labels: Sequence[str], ids: Sequence[int]):
        self.labels, self.ids = list(labels), list(ids)
        self.reference = [tuple(O.bodies[i].state.pos) for i in self.ids]
        self.time: list[float] = []
        self.x: dict[str, list[float]] = {label: [] for label in self.labels}
        self.y: dict[str, list[float]] = {label: [] for label in self.labels}

    def record(self) -> None:
        self.time.append(O.time)
        for label, i, ref in zip(self.labels, self.ids, self.reference):
            p = O.bodies[i].state.pos
            self.x[label].append(p[0] - ref[0])
            self.y[label].append(p[1] - ref[1])

    def total(self, label: str) -> list[float]:
        return [(dx * dx + dy * dy) ** 0.5 for dx, dy in zip(self.x[label], self.y[label])]

    def direction(self, label: str, still: float) -> list[float]:
        """Y/X, the direction of the point's displacement since the start (the thesis' dY/dX,
        Fig 5-21 c: a steady value is a steady sense of motion); NaN while the point has moved
        less than ``still`` [m], where the ratio of two round-off-sized numbers is noise."""
        return [dy / dx if dx != 0 and (dx * dx + dy * dy) ** 0.5 >= still else math.nan
                for dx, dy in zip(self.x[label], self.y[label])]

    def rate_since(self, label: str, since: float) -> float:
        """How fast [m/s] the point's total displacement changed from the record nearest the
        simulated time ``since`` to the last record (0 with no time between): a column still
        toppling keeps moving, one that only rattles does not."""
        start = min(range(len(self.time)), key=lambda i: abs(self.time[i] - since))
        span = self.time[-1] - self.time[start]
        total = self.total(label)
        return abs(total[-1] - total[start]) / span if span > 0 else 0.0

    def as_dict(self) -> dict[str, Any]:
        return {"labels": self.labels, "ids": self.ids, "reference": self.reference, "time": self.time,
                "x": self.x, "y": self.y}

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> "MonitoringPoints":
        points = cls.__new__(cls)
        points.labels, points.ids = d["labels"], d["ids"]
        points.reference = [tuple(r) for r in d["reference"]]
        points.time, points.x, points.y = d["time"], d["x"], d["y"]
        return points


def column_top_points(layout: columns.ColumnLayout, ids: Sequence[int]) -> MonitoringPoints:
    """Monitoring points at the column tops, labelled as in the thesis (``G-7``): of ``ids``,
    the disc nearest each column's top centre. A column holding none of them (at coarse
    resolution a toe column a few discs high can come out of the packing empty) has no
    point, and the console says so."""
    nearest: dict[int, tuple[float, int]] = {}
    for i in ids:
        x, y = tuple(O.bodies[i].state.pos)[:2]
        k = layout.column_of(x)
        if k:
            cx, cy = layout.top_centre(k)
            distance = (x - cx) ** 2 + (y - cy) ** 2
            nearest[k] = min(nearest.get(k, (distance, i)), (distance, i))
    for k in range(1, layout.count + 1):
        if k not in nearest:
            print(f"column {analysis.column_label(k)}: no discs, no monitoring point")
    ordered = sorted(nearest)
    return MonitoringPoints([analysis.column_label(k) for k in ordered], [nearest[k][1] for k in ordered])
