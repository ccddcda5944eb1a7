"""A tilting-table run to failure (thesis §5.2, Fig 5-7): the model comes to rest on the level
table, gravity turns slowly to the start tilt, then by a step per stage until a stage fails;
the failure may come to rest and the tilting go on; after the failure the run goes on so that
the failure surface develops. The run is checkpointed after every stage and every
``checkpoint_every`` wall seconds, and a run made from its checkpoint continues in the phase it
stopped in (level, jointing, ramp, stage, arrest, post, analysis); with ``exact_resume`` as the
run that never stopped would have, to the last bit. Runs of one rock that differ only in what is
done to it once it has settled (its joints) may share the settled scene (``settled_store``)."""
from __future__ import annotations

import hashlib
import json
import os
from dataclasses import dataclass, fields
from typing import Any, Callable, Optional, Sequence

import numpy as np
from yade import O

from toppling.analyse import failure
from toppling.build import bonding, columns, engines
from toppling.checks import require
from toppling.io import paraview
from toppling.load import tilting
from toppling.run.steps import run_checked
from toppling.run.checkpoint import Checkpoint
from toppling.run.monitoring import MonitoringPoints
from toppling.run.progress import Progress

# parameters that may change between a run and its continuation
FREE = ("resume", "checkpoint_every", "max_tilt", "post_failure_time", "max_wall_time", "settled_dir")
ALIGN_EVERY = 10  # chunks between alignments with exact_resume (Checkpoint.align)


@dataclass
class TiltProtocol:
    """How the table tilts: the model settles at ``settle_tilt`` [deg] (0: the level table; a
    slope built in its table frame settles at its own tilt), then turns at ``tilt_rate`` [deg/s]
    to ``start_tilt`` [deg], then ``step`` [deg] per stage, each step ramped at ``stage_rate``
    [deg/s] (0: at once), up to ``max_tilt``. ``settle_damping``: NewtonIntegrator's local
    damping while it settles, ``damping`` while it tilts. ``arrest_time`` [s]: a failure that
    comes to rest within it is not the slope's and the tilt goes on (0: the first failing stage
    is the failure).
    ``post_failure_time`` [s]: the run after the failure. ``checkpoint_every`` [wall s].
    ``max_wall_time`` [wall s, over every run of one out folder]: the run stops there, saved,
    with the reason in its summary, and the same command with a larger one continues it (0: no
    limit; every phase also ends at its simulated time limit). ``exact_resume`` 1: a run resumed
    from a checkpoint ends bit for bit as the run that never stopped (Checkpoint.align every
    ALIGN_EVERY chunks; a realigned YADE scene steps up to 2x slower); 0: it ends as a run
    whose last bits differ."""
    start_tilt: float
    step: float
    max_tilt: float
    tilt_rate: float
    stage_rate: float
    damping: float
    settle_damping: float
    arrest_time: float
    post_failure_time: float
    checkpoint_every: float
    max_wall_time: float = 0.0
    exact_resume: int = 0
    settle_tilt: float = 0.0

    def __post_init__(self):
        require("settle_tilt", self.settle_tilt, "[0, 90)")
        require("start_tilt", self.start_tilt, f"[{self.settle_tilt:g}, 90)")  # settle_tilt <= start_tilt
        require("max_tilt", self.max_tilt, f"[{self.start_tilt}, 90)")  # start_tilt <= max_tilt
        for name in ("step", "tilt_rate", "checkpoint_every"):
            require(name, getattr(self, name), "(0, inf)")
        for name in ("stage_rate", "arrest_time", "post_failure_time", "max_wall_time"):  # 0: at once, none, none, none
            require(name, getattr(self, name), "[0, inf)")
        engines.check_damping(self.damping, "damping")
        engines.check_damping(self.settle_damping, "settle_damping")
        require("exact_resume", self.exact_resume, "whole [0, 1]")

    @classmethod
    def from_params(cls, params: Any) -> "TiltProtocol":
        """The protocol from an object with these attributes (``yade.params.table``; those with
        a default may be missing)."""
        return cls(**{f.name: getattr(params, f.name) for f in fields(cls) if hasattr(params, f.name)})


def fresh_state(inputs: dict[str, Any], layout: columns.ColumnLayout, ids: list[int], bands: dict[str, list[int]],
                start_tilt: float) -> dict[str, Any]:
    """The checkpointed state of a run starting on a built scene: its discs ``ids`` and the
    groups it watches, ``bands`` (discs near each column's top, by column label)."""
    built = tilting.positions(ids).tolist()  # the pictures' reference; "reference" moves with each equilibrium
    return {"inputs": inputs, "layout": vars(layout), "ids": ids, "built": built, "watched": list(bands.values()),
            "watched_columns": list(bands), "tilt": start_tilt, "failure_tilt": None, "reference": list(built),
            "stages": [], "energy": [], "chunks": 0}


def settled_store(folder: str, inputs: dict[str, Any], differ_in: Sequence[str]) -> Optional[Checkpoint]:
    """Where runs whose ``inputs`` are the same apart from ``differ_in`` (what is done to the rock
    once it has settled, e.g. its joints) and the run's own (``out``, ``description``, FREE) keep
    their one settled scene: ``<folder>/<digest of the other inputs>``; None without a folder.
    The scene is as the code that settled it made it: empty the folder when that code changes."""
    if not folder:
        return None
    skip = set(differ_in) | set(FREE) | {"out", "description"}
    rock = {k: v for k, v in inputs.items() if k not in skip}
    digest = hashlib.sha1(json.dumps(rock, sort_keys=True, default=str).encode()).hexdigest()[:16]
    return Checkpoint(os.path.join(folder, digest))


class Stopped(Exception):
    """The run reached max_wall_time; the message says where and how to go on."""


def stage_line(stage: dict) -> str:
    """The log line of a finished stage (the ones `grep '^tilt'` finds)."""
    how = f" by {stage['failed_by']}" if "failed_by" in stage else ""
    if stage["outcome"] == "equilibrium" and stage.get("at_time_limit"):
        how = " at max_stage_time (still moving, but less than rest_speed over the stage)"
    gone = stage.get("gone", [])
    alone = f"; {', '.join(gone)} toppled off alone" if stage["outcome"] == "equilibrium" and gone else ""
    return f"tilt {stage['tilt']:.1f} deg: {stage['outcome']}{how} (a column top moved {stage['moved_mm']:.1f} mm{alone})"


def arrest_line(stage: dict, arrest_time: float) -> str:
    """The log line (also `grep '^tilt'`) that says whether a failing stage's failure arrested."""
    after = stage["came_to_rest_after_s"]
    if after is None:
        return f"tilt {stage['tilt']:.1f} deg: still moving {arrest_time:g} s after the failure: the slope collapses"
    left = f"; {', '.join(stage['left_table'])} left the table" if stage["left_table"] else ""
    phi = ", ".join(f"{p:.1f}" for p in stage.get("phi_deg", [])) or "-"
    return (f"tilt {stage['tilt']:.1f} deg: came to rest {after:.2f} s after the failure "
            f"({stage['discs_off_table']} discs off the table{left}, {stage['breaks']} breaks so far; "
            f"phi {phi} deg): tilting on")


def sort_breaks_before_stages(before: dict, ramp_tilt: Callable[[float], float]) -> dict:
    """Add to ``before`` (``breaks_before_stages``: the breaks of the level table, then of the
    ramp, first in the bond law's record) how many of each phase freed a loose disc and the tilt
    (``ramp_tilt`` of the simulated time) at which the ramp first cracked the rock
    (``bonding.rock_breaks``)."""
    rock = {"level": bonding.rock_breaks(0, before["level"]),  # each judged at its phase's end
            "ramp": bonding.rock_breaks(before["level"], before["ramp"])}
    before["loose"] = {phase: before[phase] - len(breaks) for phase, breaks in rock.items()}
    if rock["ramp"]:
        before["first_ramp_crack_deg"] = ramp_tilt(engines.break_record().breakTime[rock["ramp"][0]])
    return before


def cracks(breaks: dict, phase: str) -> int:
    """The bonds of ``breaks`` (``breaks_before_stages``) that broke in ``phase`` (level, ramp)
    inside the rock, besides those that freed a loose disc (``bonding.rock_breaks``)."""
    return breaks[phase] - breaks.get("loose", {}).get(phase, 0)


def ramp_warning(breaks: dict) -> str:
    """The warning for bonds of the rock broken before the first stage (``breaks``:
    ``breaks_before_stages``), empty if none: the first stage's slope is then already cracked
    and its failure tilt may be lower than the intact slope's. Breaks that freed a loose disc
    are debris coming off, not cracks: they are counted, not warned of."""
    level, ramp = cracks(breaks, "level"), cracks(breaks, "ramp")
    if not (level or ramp):
        return ""
    advice = []
    if level:  # no tilt yet: a lower start_tilt cannot spare these bonds
        advice.append("bonds that break on the level table carry overlaps locked into the packing or the slope's "
                      "own weight: shrink the overlaps before bonding (packing.shrink_overlaps) or raise the bond "
                      "strengths")
    if ramp:
        advice.append(f"rerun with a start_tilt below {breaks['first_ramp_crack_deg']:.1f} deg, where the ramp "
                      "first cracked the rock, to judge in stages the tilts the ramp passed")
    return (f"WARNING: {level} bonds of the rock broke on the level table and {ramp} on the ramp to "
            "start_tilt: the slope entered its first stage cracked and its failure tilt may be low; "
            + "; ".join(advice))


def arrested_text(arrested: list[dict]) -> str:
    """The failures that came to rest, for a run's last line."""
    tilts = ", ".join(f"{failure['tilt']:.1f}" for failure in arrested)
    return f" after failures that came to rest at {tilts} deg" if arrested else ""


class TiltRun:
    """One run of ``protocol`` on the scene of ``state`` (``fresh_state`` or a checkpoint's),
    stages judged by ``criteria`` on the watched groups; ``points`` are the monitoring points,
    ``series`` the ParaView series (a snapshot at the start tilt before the first stage, and
    after every stage). ``rmin``, ``rmax``: the packing's radii, which set the analysis'
    resolution and where the table ends (a disc whose centre fell 2 Rmax below the table has
    left it)."""

    def __init__(self, protocol: TiltProtocol, criteria: tilting.StageCriteria, checkpoint: Checkpoint,
                 state: dict[str, Any], points: MonitoringPoints, series: paraview.ParaViewSeries,
                 rmin: float, rmax: float, settled: Optional[Callable[[], None]] = None,
                 store: Optional[Checkpoint] = None):
        self.protocol, self.criteria, self.checkpoint, self.state = protocol, criteria, checkpoint, state
        self.settled = settled  # what the model does once it stands, before the tilt (e.g. a slope's joints)
        self.store = store  # where the settled scene is kept for the runs that differ only in ``settled``
        self.points, self.series, self.rmin, self.rmax = points, series, rmin, rmax
        self.layout = columns.ColumnLayout(**state["layout"])
        self.off_table = -2 * rmax
        self.ids, self.watched = state["ids"], state["watched"]
        if state.get("phase") is None and criteria.fail_columns > len(self.watched):  # a resumed run may watch fewer
            raise ValueError(f"fail_columns = {criteria.fail_columns} is invalid: it must be at most the number of "
                             f"watched groups ({len(self.watched)})")
        self.watched_columns = state["watched_columns"]
        self.progress = Progress(energy=lambda: state["energy"][-1][2])  # what on_chunk just recorded
        self.earlier_wall_time = state.get("wall_time", 0.0)  # of the runs this one resumes
        self.last_save = self.progress.wall_time
        p = protocol
        self.known_length = {"ramp": (f"ramp to {p.start_tilt:g} deg", self.ramp_duration()),
                             "arrest": ("after failure, at most", p.arrest_time),
                             "post": ("after failure", p.post_failure_time)}  # phases whose ETA is their end

    @property
    def failure_tilt(self) -> Optional[float]:
        return self.state["failure_tilt"]

    def ramp_duration(self) -> float:
        p = self.protocol
        return (p.start_tilt - p.settle_tilt) / p.tilt_rate

    def wall_time(self) -> float:
        return self.earlier_wall_time + self.progress.wall_time

    def slope_energy(self) -> float:
        """The kinetic energy of the discs still on the table: a column fallen off it is no longer the slope's."""
        return tilting.kinetic_energy_above(self.ids, self.off_table)

    def save_checkpoint(self, aligned: bool = False, to: Optional[Checkpoint] = None) -> None:
        """Save the run in its checkpoint (or ``to``; with exact_resume aligned, Checkpoint.align,
        unless ``aligned`` already, so that it resumes bit for bit: then called only at moments
        every run of the same inputs passes, a phase's end or an aligned chunk)."""
        if self.protocol.exact_resume and not aligned:
            self.checkpoint.align()
        state = self.state
        state["points"], state["series"], state["wall_time"] = self.points.as_dict(), self.series.state(), self.wall_time()
        (to or self.checkpoint).save(state)
        self.last_save = self.progress.wall_time

    def keep_settled(self) -> None:
        """Keep the settled scene in the store. Aligned whatever exact_resume says: the runs that
        start from the store go on from a scene passed through its serialization, and so does
        this one, so that every run of the rock goes on from the same bits."""
        self.checkpoint.align()
        self.save_checkpoint(aligned=True, to=self.store)

    def on_chunk(self) -> None:
        self.state["chunks"] += 1
        exact = self.protocol.exact_resume
        aligned = not exact or self.state["chunks"] % ALIGN_EVERY == 0  # where a checkpoint may be saved
        if aligned and exact:  # a run resumed from here goes on as this one does
            self.checkpoint.align()
        self.points.record()
        self.state["energy"].append((O.time, tilting.current_tilt(), self.slope_energy()))  # the ramp shows as one
        phase, p = self.state["phase"], self.protocol
        if phase["name"] in self.known_length:
            label, length = self.known_length[phase["name"]]
            self.progress(f"tilt {tilting.current_tilt():.1f} deg, {label}",
                          remaining_time=max(0.0, length - (O.time - phase["start"])))
        else:  # the level table's length is not known; a stage's ETA is to max_tilt, an upper bound (it ends at failure)
            span = p.max_tilt - p.start_tilt
            bound = None
            if phase["name"] == "stage":  # a stage of a fine packing can ring for hours before its time limit
                bound = max(0.0, self.criteria.max_stage_time - (O.time - phase["start"]))
            self.progress(f"tilt {tilting.current_tilt():.1f} deg",
                          (self.state["tilt"] - p.start_tilt) / span if span > 0 else None, stage_bound=bound)
        if aligned and self.progress.wall_time - self.last_save > p.checkpoint_every:  # a stage may run for hours
            self.save_checkpoint(aligned=True)
        if aligned and 0 < p.max_wall_time < self.wall_time():
            self.save_checkpoint(aligned=True)
            raise Stopped(f"max_wall_time = {p.max_wall_time:g} s reached in the {self.state['phase']['name']} phase at "
                          f"{tilting.current_tilt():.1f} deg: run the same command with a larger max_wall_time (0: no "
                          "limit) to continue")

    def at_time_limit(self, phase: dict) -> bool:
        """Whether the stage of ``phase`` ran to max_stage_time (rather than ending at rest or in a collapse)."""
        return O.time - phase["start"] > self.criteria.max_stage_time

    def begin(self, name: str, start: Optional[float] = None, **extra) -> dict:
        """Enter a phase of the run; the checkpoint records it and when it began (now by
        default), so that a resumed run continues it rather than starting it again."""
        self.state["phase"] = dict(name=name, start=O.time if start is None else start, **extra)
        return self.state["phase"]

    def run_stage(self, alpha: float, phase: dict) -> str:
        p = self.protocol
        if p.stage_rate > 0 and alpha > p.start_tilt:  # the step as a ramp: no dynamic overshoot
            tilting.ramp(alpha - p.step, alpha, p.step / p.stage_rate, self.on_chunk, start=phase["start"])
        return tilting.run_stage(alpha, self.watched, np.array(phase["reference"]), self.criteria, self.on_chunk,
                                 start=phase["start"], history=phase.setdefault("watch", []))

    def analyse(self, tilt: float, onset: Optional[dict] = None) -> dict:
        """The failure of the last stage (at ``tilt``), from the displacements since the last
        equilibrium and every crack so far, in the slope frame (x normal to the columns towards
        the face, y up the columns); with ``onset`` (the state's) at the failing stage's end: its
        positions, its cracks, and the tops that moved in its last chunk."""
        reference = np.array(self.state["reference"])
        failed_at = self.state["stages"][-1]["time"]
        if onset is None:  # a top still moving since the failure
            now, breaks, since, until = tilting.positions(self.ids), None, failed_at, None
        else:
            now, breaks, since, until = np.array(onset["positions"]), onset["breaks"], failed_at - self.criteria.chunk, failed_at
        index = {i: n for n, i in enumerate(self.ids)}
        result = failure.table_failure(
            self.layout, reference, now, {label: index[i] for label, i in zip(self.points.labels, self.points.ids)},
            lambda label: self.points.rate_since(label, since, until) > self.criteria.rest_speed,
            [tuple(p)[:2] for p in engines.break_record().breakPosition][:breaks], tilt, floor=self.off_table,
            band=2 * self.rmax, least_motion=self.rmin)  # the model's resolution
        return {**result, "disp": now - reference, "now": now}

    def next_stage(self) -> dict:
        """The slope stands (or stands again): its positions are the reference of the next stage's."""
        self.state["reference"] = tilting.positions(self.ids).tolist()
        self.state["tilt"] += self.protocol.step
        return self.begin("stage", reference=tilting.medians(self.watched).tolist())

    def collapse(self) -> dict:
        """The last stage's failure is the slope's: run on after it from the moment it failed."""
        self.state["failure_tilt"] = self.state["tilt"]
        return self.begin("post", start=self.state["stages"][-1]["time"])

    def arrested(self, stage: dict) -> None:
        """The failure of ``stage`` came to rest: record it, and watch only what is left on
        the table (what fell off falls on for ever and would fail every later stage)."""
        kept = tilting.on_table(self.watched, self.off_table)
        stage["left_table"] = [label for label, group in zip(self.watched_columns, kept) if not group]
        stage["discs_off_table"] = sum(O.bodies[i].state.pos[1] <= self.off_table for i in self.ids)
        stage["breaks"] = engines.broken_bonds()
        failure = self.analyse(stage["tilt"])  # before the next stage moves the reference
        stage["phi_deg"] = [plane.phi_deg for plane in failure["planes"]]
        stage["s_over_h"], stage["t_over_h"] = failure["s_over_h"], failure["t_over_h"]
        self.watched[:] = kept
        self.watch([bool(group) for group in kept])

    def watch(self, keep: list[bool]) -> None:
        """Judge later stages on the watched columns that ``keep`` marks; the checkpoint keeps the choice."""
        self.watched[:] = [group for group, k in zip(self.watched, keep) if k]
        self.watched_columns[:] = [label for label, k in zip(self.watched_columns, keep) if k]
        self.state["watched_columns"] = self.watched_columns

    def judge_stage(self, phase: dict) -> dict:
        """Run the stage of ``phase`` to its outcome and record it. A stage that stands watches
        no more the columns that toppled off alone in it: they are no longer the slope's, and
        counted again with one more column they would fail a later stage the slope stands."""
        state = self.state
        outcome = self.run_stage(state["tilt"], phase)
        now, reference = tilting.medians(self.watched), np.array(phase["reference"])
        off = tilting.gone(now, reference, self.criteria)
        judged = ~off if outcome == "equilibrium" else np.ones_like(off)  # a column gone off the table does not count
        moved = float(np.linalg.norm(now - reference, axis=1)[judged].max(initial=0.0))
        stage = {"tilt": state["tilt"], "outcome": outcome, "time": O.time, "steps": O.iter,
                 "at_time_limit": self.at_time_limit(phase),
                 "moved_mm": 1e3 * moved,  # a local collapse that came to rest shows here
                 "gone": [c for c, gone in zip(self.watched_columns, off) if gone]}
        if outcome == "failed":  # a collapse or a creep: whoever weighs the failure tilt needs to know which
            stage["failed_by"] = "fail_displacement" if self.criteria.collapsed(off) else "max_stage_time"
            state["onset"] = {"positions": tilting.positions(self.ids).tolist(), "breaks": engines.broken_bonds()}
        state["stages"].append(stage)
        print(stage_line(stage), flush=True)
        if outcome == "equilibrium":
            self.watch(list(~off))
        self.series.snapshot()
        return stage

    def judge_arrest(self, phase: dict) -> dict:
        """Run on after the last stage's failure: it comes to rest (the tilt goes on) or not (the slope collapses)."""
        stage = self.state["stages"][-1]
        stage["came_to_rest_after_s"] = tilting.run_arrest(self.watched, self.off_table, self.criteria,
                                                           self.protocol.arrest_time, self.on_chunk,
                                                           start=phase["start"])
        if stage["came_to_rest_after_s"] is None:
            phase = self.collapse()
        else:
            self.arrested(stage)
            self.series.snapshot()
            phase = self.next_stage()
        print(arrest_line(stage, self.protocol.arrest_time), flush=True)
        return phase

    def run(self) -> Optional[float]:
        """Settle at settle_tilt (the level table), tilt to start_tilt, then in stages until a stage fails
        (then run post_failure_time after the failure) or max_tilt stands. Returns the failure
        tilt [deg], None if the slope stood up to max_tilt or the run stopped at max_wall_time
        (``state["stopped"]`` says where)."""
        self.state.pop("stopped", None)
        try:
            return self.run_phases()
        except Stopped as stop:
            self.state["stopped"] = str(stop)
            print(f"stopped: {stop}", flush=True)
            return None

    def run_phases(self) -> Optional[float]:
        state, p = self.state, self.protocol
        for done in state["stages"]:  # a resumed run's log (yade-batch overwrites it) still lists every stage
            print(stage_line(done), flush=True)
            if "came_to_rest_after_s" in done:
                print(arrest_line(done, p.arrest_time), flush=True)
        phase = state.get("phase") or self.begin("level", reference=tilting.medians(self.watched).tolist())
        if phase["name"] == "level":
            engines.set_local_damping(p.settle_damping)
            if self.run_stage(p.settle_tilt, phase) == "failed":
                raise RuntimeError(f"the model does not stand at settle_tilt = {p.settle_tilt:g} deg, where it settles: "
                                   "check the outline and the joints")
            limit = " (at max_stage_time: still moving, but less than rest_speed)" if self.at_time_limit(phase) else ""
            print(f"settled at {p.settle_tilt:g} deg: equilibrium after {O.time - phase['start']:.3f} s{limit}", flush=True)
            state["breaks_before_stages"] = {"level": engines.broken_bonds()}
            phase = self.begin("jointing")
            if self.store:
                self.keep_settled()
        if phase["name"] == "jointing":
            if self.settled:
                self.settled()
            phase = self.begin("ramp")
        engines.set_local_damping(p.damping)  # from here on the loading's, also in a resumed run
        if phase["name"] == "ramp":
            tilting.ramp(p.settle_tilt, p.start_tilt, self.ramp_duration(), self.on_chunk, start=phase["start"])
            before = self.count_ramp_breaks(phase["start"])
            if warning := ramp_warning(before):  # said now: the user may stop the run rather than wait for its stages
                print(warning, flush=True)
            self.series.snapshot()  # the slope its first stage starts from: a first-stage failure is seen from it
            phase = self.begin("stage", reference=tilting.medians(self.watched).tolist())
        while state["failure_tilt"] is None and state["tilt"] <= p.max_tilt + 1e-9:
            if phase["name"] == "stage":
                if self.judge_stage(phase)["outcome"] == "failed":
                    phase = self.begin("arrest") if p.arrest_time > 0 else self.collapse()
                else:
                    phase = self.next_stage()
                self.save_checkpoint()
            if phase["name"] == "arrest":  # a failure that comes to rest within arrest_time is not the slope's
                phase = self.judge_arrest(phase)
                self.save_checkpoint()
        if state["failure_tilt"] is not None:
            self.run_after_failure(phase)
        return state["failure_tilt"]

    def count_ramp_breaks(self, start: float) -> dict:
        """Add to ``breaks_before_stages`` the bonds broken on the ramp that began at ``start``
        and tell them from those that freed loose discs (``sort_breaks_before_stages``)."""
        p, before = self.protocol, self.state["breaks_before_stages"]
        before["ramp"] = engines.broken_bonds() - before["level"]
        return sort_breaks_before_stages(before, lambda t: min(p.start_tilt, p.settle_tilt + p.tilt_rate * (t - start)))

    def run_after_failure(self, phase: dict) -> None:
        """Let the failure surface develop for post_failure_time after the failure (also when a
        finished run is run again with a longer one)."""
        if phase["name"] == "analysis" and O.time - self.state["stages"][-1]["time"] < self.protocol.post_failure_time:
            phase = self.begin("post", start=self.state["stages"][-1]["time"])
        if phase["name"] == "post":
            while O.time - phase["start"] < self.protocol.post_failure_time:
                run_checked(self.criteria.chunk, "the post-failure run")
                self.on_chunk()
            self.series.snapshot()
            self.begin("analysis")
            self.save_checkpoint()

    def record(self) -> dict:
        """What every summary holds besides the failure: cracks, failures that came to rest, size and cost."""
        modes = engines.break_record().breakMode
        failed = [stage for stage in self.state["stages"] if stage["outcome"] == "failed"]
        keys = ("tilt", "came_to_rest_after_s", "left_table", "discs_off_table", "breaks", "moved_mm", "phi_deg",
                "s_over_h", "t_over_h")
        arrested = [{key: stage.get(key) for key in keys} for stage in failed if stage.get("came_to_rest_after_s")]
        return dict(stopped=self.state.get("stopped"), settled_from=self.state.get("settled_from"),
                    first_failure_tilt_deg=failed[0]["tilt"] if failed else None, arrested_failures=arrested,
                    breaks_before_stages=self.state.get("breaks_before_stages"),
                    tensile_breaks=modes.count(2), shear_breaks=modes.count(3), discs=len(self.ids),
                    stages=self.state["stages"], steps=O.iter, simulated_time=O.time, wall_time=self.wall_time())
