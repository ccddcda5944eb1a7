"""toppling.tilt_run: the staged tilt of a block on a joint fails at the first stage past the
joint's friction angle, also when the run stops at a stage and continues from its checkpoint."""
import dataclasses
import json
import math
import os
import re

import numpy as np
import pytest
from yade import O
from yade.wrapper import Law2_ScGeom_JCFpmPhys_JointedCohesiveFrictionalPM, ParallelBondMat, SmoothJointPhys

from conftest import ROCK
from toppling.build import bonding, columns, engines, geometry, jcfpm, packing
from toppling.build.discs import disc
from toppling.io import tilt_report
from toppling.load import tilting
from toppling.models import incline
from toppling.run import tilt_run
from toppling.run.monitoring import MonitoringPoints
from toppling.run.checkpoint import Checkpoint

RMIN, RMAX = 0.012 / 2.5, 0.012
FRICTION_DEG = math.degrees(math.atan(0.4))  # 21.8 deg: stages at 17, 19, 21 stand, 23 slides
CRITERIA = tilting.StageCriteria(chunk=0.02, rest_speed=1e-3, fail_displacement=2e-3, max_stage_time=0.3)


class Series:
    """The ParaView series' part the run uses, without files."""

    def __init__(self, state=None):
        self.snapshots = (state or {}).get("snapshots", 0)

    def snapshot(self):
        self.snapshots += 1

    def state(self):
        return {"snapshots": self.snapshots}


def protocol(**changes) -> tilt_run.TiltProtocol:
    return tilt_run.TiltProtocol(**{**dict(start_tilt=17.0, step=2.0, max_tilt=30.0, tilt_rate=50.0, stage_rate=10.0,
                                           damping=0.5, settle_damping=0.5, arrest_time=0.0, post_failure_time=0.02,
                                           checkpoint_every=600.0), **changes})


def fresh_run(tmp_path, p: tilt_run.TiltProtocol, criteria: tilting.StageCriteria = CRITERIA,
              **settling) -> tilt_run.TiltRun:
    """The block on its joint, built afresh; ``settling``: TiltRun's ``settled`` and ``store``."""
    setup = incline.build(0.1, 0.05, RMIN, RMAX, ROCK, FRICTION_DEG)
    layout = columns.ColumnLayout(toe_x=0.15, width=0.1, heights=[0.05])  # the block as column A-1
    state = tilt_run.fresh_state({"case": "block"}, layout, setup.block + setup.base, {"A-1": setup.block},
                                 p.start_tilt)
    state["points"] = MonitoringPoints(["A-1"], [setup.toe]).as_dict()
    return saved_run(tmp_path, p, state, criteria, **settling)


def saved_run(tmp_path, p: tilt_run.TiltProtocol, state: dict, criteria: tilting.StageCriteria = CRITERIA,
              **settling) -> tilt_run.TiltRun:
    return tilt_run.TiltRun(p, criteria, Checkpoint(str(tmp_path)), state, MonitoringPoints.from_dict(state["points"]),
                            Series(state.get("series")), RMIN, RMAX, **settling)


def cantilever_run(tmp_path, p: tilt_run.TiltProtocol, tensile_strength: float, shrink: bool = True) -> tilt_run.TiltRun:
    """A 2 x 10 cm column bonded to a fixed base: tilted, it bends like a cantilever. Unless
    ``shrink``, its bonds are installed over the packing's overlaps and so start loaded."""
    rmin, rmax, b, h = 0.0015, 0.003, 0.02, 0.1
    section = [(0, -0.03), (0.1, -0.03), (0.1, 0), (0.06, 0), (0.06, h), (0.04, h), (0.04, 0), (0, 0)]
    discs = packing.pack_polygon(geometry.region(section), rmin, rmax, 0.2).discs
    discs = packing.shrink_overlaps(discs) if shrink else discs
    mat = ParallelBondMat(frictionAngle=0.5, bondTensileStrength=tensile_strength, bondCohesion=1e12, **ROCK)
    base = [O.bodies.append(disc((x, y), r, mat, fixed=True)) for x, y, r in discs if y < 0]
    column = [O.bodies.append(disc((x, y), r, mat)) for x, y, r in discs if y >= 0]
    O.engines = engines.engines(gravity=(0, -tilting.G, 0), local_damping=0.0)
    floaters = set(bonding.remove_floaters(0.05 * rmin, ids=column))
    column = [i for i in column if i not in floaters]
    bonding.bond_within_gap(0.05 * rmin)
    state = tilt_run.fresh_state({"case": "cantilever"}, columns.ColumnLayout(toe_x=0.06, width=b, heights=[h]),
                                 column + base, {"A-1": column}, p.start_tilt)
    points = MonitoringPoints(["A-1"], [max(column, key=lambda i: O.bodies[i].state.pos[1])])
    return tilt_run.TiltRun(p, CRITERIA, Checkpoint(str(tmp_path)), state, points, Series(), rmin, rmax)


def resumed_run(tmp_path, p: tilt_run.TiltProtocol) -> tilt_run.TiltRun:
    return saved_run(tmp_path, p, Checkpoint(str(tmp_path)).load())


def tilts(run: tilt_run.TiltRun) -> list[tuple[float, str]]:
    return [(stage["tilt"], stage["outcome"]) for stage in run.state["stages"]]


def test_the_block_fails_at_the_first_stage_past_its_friction_angle_and_runs_on_after_it(empty_scene, tmp_path, capsys):
    run = fresh_run(tmp_path, protocol())
    assert run.run() == 23.0
    assert tilts(run) == [(17.0, "equilibrium"), (19.0, "equilibrium"), (21.0, "equilibrium"), (23.0, "failed")]
    assert run.state["phase"]["name"] == "analysis" and O.time - run.state["stages"][-1]["time"] >= 0.02
    assert "tilt 23.0 deg: failed" in capsys.readouterr().out
    tilt_report.report(run, str(tmp_path), {"failure_tilt_deg": 22, "phi_deg": [0]}, "block")
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["failure_tilt_deg"] == 23.0 and summary["first_failure_tilt_deg"] == 23.0
    assert summary["inputs"] == {"case": "block"} and len(summary["stages"]) == 4
    assert summary["two_planes_p"] is None and summary["phi_overall_deg"] is None  # one column: no surface
    O.reset()
    longer = resumed_run(tmp_path, protocol(post_failure_time=0.06))  # a finished run given a longer run after failure
    assert longer.run() == 23.0 and O.time - longer.state["stages"][-1]["time"] >= 0.06
    assert longer.state["phase"]["name"] == "analysis" and len(longer.state["stages"]) == 4


def test_a_run_stopped_at_max_tilt_continues_from_its_checkpoint_to_the_same_failure(empty_scene, tmp_path, capsys):
    stopped = fresh_run(tmp_path, protocol(max_tilt=19.0))
    assert stopped.run() is None and tilts(stopped) == [(17.0, "equilibrium"), (19.0, "equilibrium")]
    tilt_report.report(stopped, str(tmp_path), {"failure_tilt_deg": 22, "phi_deg": [0]}, "block")
    assert "no failure up to max_tilt = 19.0 deg" in capsys.readouterr().out
    assert json.loads((tmp_path / "summary.json").read_text())["stable_up_to_deg"] == 19.0
    O.reset()
    continued = resumed_run(tmp_path, protocol())
    assert continued.run() == 23.0
    assert tilts(continued) == [(17.0, "equilibrium"), (19.0, "equilibrium"), (21.0, "equilibrium"), (23.0, "failed")]
    log = capsys.readouterr().out
    assert log.index("tilt 17.0 deg: equilibrium") < log.index("tilt 23.0 deg: failed")  # the log lists every stage
    assert continued.series.snapshots == 6  # one at the start tilt, one per stage, one after the failure's run


def test_bonds_broken_by_the_ramp_to_the_start_tilt_are_counted_and_reported(empty_scene, tmp_path, capsys):
    # the bending tension at the column's foot, 3 rho g h^2 sin(alpha) / b, is 17 kPa at 30 deg for a solid 2 cm
    # section and ~0 on the level table (the overlaps shrunk, bonds are stress-free there): 8 kPa breaks on the ramp
    run = cantilever_run(tmp_path, protocol(start_tilt=30.0, max_tilt=30.0), tensile_strength=8e3)
    run.run()
    before = run.state["breaks_before_stages"]
    assert before["level"] == 0 and before["ramp"] > 0 and 0 < before["first_ramp_crack_deg"] < 30
    assert f"WARNING: 0 bonds of the rock broke on the level table and {tilt_run.cracks(before, 'ramp')} on the ramp" \
        in capsys.readouterr().out
    tilt_report.report(run, str(tmp_path), {"failure_tilt_deg": 0, "phi_deg": [0]}, "cantilever")
    assert f"rerun with a start_tilt below {before['first_ramp_crack_deg']:.1f} deg" in capsys.readouterr().out
    assert json.loads((tmp_path / "summary.json").read_text())["breaks_before_stages"] == before


def test_a_run_handed_to_jcfpm_counts_and_reports_its_cracks(empty_scene, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)  # JCFpm writes its cracks' file in the working directory
    run = cantilever_run(tmp_path, protocol(start_tilt=30.0, max_tilt=30.0), tensile_strength=8e3)
    jcfpm.convert(cracks=True)
    run.run()
    law = engines.functor(Law2_ScGeom_JCFpmPhys_JointedCohesiveFrictionalPM)
    record = jcfpm.CrackRecord.of_scene()
    assert len(record.breakMode) == law.nbTensCracks + law.nbShearCracks == engines.broken_bonds() > 0
    assert record.breakMode.count(2) == law.nbTensCracks and all(0 < t <= O.time for t in record.breakTime)
    tilt_report.report(run, str(tmp_path), {"failure_tilt_deg": 0, "phi_deg": [0]}, "cantilever")
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["tensile_breaks"] + summary["shear_breaks"] == len(record.breakMode)
    assert (tmp_path / "jcfpm_cracks.txt").exists() and not os.path.exists(record.path)  # kept with the run


def ramp_breaks(tmp_path, start_tilt: float) -> dict:
    """The bonds the ramp to ``start_tilt`` breaks in a fresh cantilever of 8 kPa bonds."""
    O.reset()
    run = cantilever_run(tmp_path / f"{start_tilt:.2f}", protocol(start_tilt=start_tilt, max_tilt=start_tilt), 8e3)
    run.run()
    return run.state["breaks_before_stages"]


def test_a_ramp_stopped_short_of_the_reported_first_crack_breaks_no_bond(empty_scene, tmp_path):
    # the advice's promise: a ramp runs the same way up to the tilt it reports, so a start_tilt half a
    # degree (10 gravity updates at 50 deg/s) below it enters its stages intact, one above it does not
    first = ramp_breaks(tmp_path, 30.0)["first_ramp_crack_deg"]
    assert ramp_breaks(tmp_path, first - 0.5)["ramp"] == 0
    above = ramp_breaks(tmp_path, first + 0.5)
    assert above["ramp"] > 0 and above["first_ramp_crack_deg"] == pytest.approx(first, abs=0.06)


def test_stages_crack_the_rock_first_in_the_stage_past_the_ramps_first_crack(empty_scene, tmp_path):
    # the cantilever staged in 2 deg steps holds uncracked up to the ramp's first-crack tilt and cracks (and
    # fails) in the stage after it
    first = ramp_breaks(tmp_path, 30.0)["first_ramp_crack_deg"]
    O.reset()
    run = cantilever_run(tmp_path / "stages", protocol(start_tilt=18.0, max_tilt=30.0), 8e3)
    run.run()
    broke = list(engines.bond_law().breakTime)
    stages = run.state["stages"]
    uncracked = [s["tilt"] for s in stages if not any(t <= s["time"] for t in broke)]
    assert uncracked == [t for t in (18.0, 20.0, 22.0, 24.0) if t < first]
    assert stages[-1]["outcome"] == "failed" and stages[-1]["tilt"] - first < 2.0


def test_bonds_broken_on_the_level_table_are_blamed_on_the_packing_not_the_ramp(empty_scene, tmp_path, capsys):
    # the same column bonded over its packing's overlaps: their locked-in force breaks a few 30 kPa bonds (80 kPa
    # none) before any tilt, most of them freeing a disc but one cracking the rock, and the ramp to 10 deg (6 kPa
    # of bending) none
    run = cantilever_run(tmp_path, protocol(start_tilt=10.0, max_tilt=10.0), tensile_strength=30e3, shrink=False)
    run.run()
    before = run.state["breaks_before_stages"]
    assert before["level"] > 0 and before["ramp"] == 0
    out = capsys.readouterr().out
    assert f"WARNING: {tilt_run.cracks(before, 'level')} bonds of the rock broke on the level table" in out
    assert "packing.shrink_overlaps" in out
    assert "rerun with a start_tilt" not in out


def test_a_ramp_that_breaks_no_bond_warns_of_nothing(empty_scene, tmp_path, capsys):
    run = cantilever_run(tmp_path, protocol(start_tilt=10.0, max_tilt=10.0), tensile_strength=8e3)  # 6 kPa
    assert run.run() is None
    assert run.state["breaks_before_stages"] == {"level": 0, "ramp": 0, "loose": {"level": 0, "ramp": 0}}
    assert "WARNING" not in capsys.readouterr().out


def test_breaks_that_only_freed_loose_discs_warn_of_nothing():
    # debris coming off is no crack (bonding.rock_breaks)
    assert tilt_run.ramp_warning({"level": 1, "ramp": 2, "loose": {"level": 1, "ramp": 2}}) == ""
    warning = tilt_run.ramp_warning({"level": 1, "ramp": 2, "loose": {"level": 1, "ramp": 1}, "first_ramp_crack_deg": 12.0})
    assert "0 bonds of the rock broke on the level table and 1 on the ramp" in warning
    assert "start_tilt below 12.0 deg" in warning


def test_a_column_that_toppled_off_alone_does_not_fail_a_later_stage_with_another(empty_scene, tmp_path):
    """fail_columns 2: a disc falling in the void from the first stage on (a column gone off the
    table, its pieces still moving) and the block sliding off at 25 deg each go alone, the fixed
    base stays; counted again, the falling disc would fail the 25 deg stage with the block (as in
    table line 288's first run). The base, then watched alone, is judged on: a stage goes on
    with fewer columns than fail_columns."""
    setup = incline.build(0.1, 0.05, RMIN, RMAX, ROCK, FRICTION_DEG)
    faller = O.bodies.append(disc((-1.0, 1.0), RMIN, O.bodies[setup.block[0]].material))
    layout = columns.ColumnLayout(toe_x=0.15, width=0.1, heights=[0.05])
    state = tilt_run.fresh_state({"case": "block"}, layout, setup.block + setup.base + [faller],
                                 {"A-1": setup.block, "B-2": [faller], "C-3": setup.base}, 17.0)
    run = tilt_run.TiltRun(protocol(step=4.0, max_tilt=29.0), dataclasses.replace(CRITERIA, fail_columns=2),
                           Checkpoint(str(tmp_path)), state, MonitoringPoints(["A-1"], [setup.toe]),
                           Series(), RMIN, RMAX)
    assert run.run() is None
    assert [(s["tilt"], s["outcome"], s["gone"]) for s in run.state["stages"]] == [
        (17.0, "equilibrium", ["B-2"]), (21.0, "equilibrium", []), (25.0, "equilibrium", ["A-1"]),
        (29.0, "equilibrium", [])]
    assert run.watched_columns == ["C-3"] and run.state["watched_columns"] == ["C-3"]


def test_a_fresh_run_refuses_more_fail_columns_than_it_watches(empty_scene, tmp_path):
    with pytest.raises(ValueError, match=r"fail_columns = 2 is invalid: it must be at most the number of watched "
                                         r"groups \(1\)"):
        fresh_run(tmp_path, protocol(), dataclasses.replace(CRITERIA, fail_columns=2))


def test_a_run_stopped_at_max_wall_time_says_why_and_the_same_command_continues_it(empty_scene, tmp_path, capsys):
    stopped = fresh_run(tmp_path, protocol(max_wall_time=1e-3))
    assert stopped.run() is None
    assert re.fullmatch(r"max_wall_time = 0.001 s reached in the level phase at \d+\.\d deg: run the same command "
                        r"with a larger max_wall_time \(0: no limit\) to continue", stopped.state["stopped"])
    tilt_report.report(stopped, str(tmp_path), {"failure_tilt_deg": 22, "phi_deg": [0]}, "block")
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["failed"] is None and summary["stopped"] == stopped.state["stopped"]
    assert "stopped before the run's end: max_wall_time" in capsys.readouterr().out
    O.reset()
    continued = resumed_run(tmp_path, protocol())
    assert continued.run() == 23.0 and "stopped" not in continued.state


def test_a_stage_that_ends_at_its_time_limit_says_so():
    stage = {"tilt": 20.0, "outcome": "equilibrium", "moved_mm": 0.1, "gone": []}
    assert tilt_run.stage_line(stage) == "tilt 20.0 deg: equilibrium (a column top moved 0.1 mm)"
    assert "equilibrium at max_stage_time (still moving" in tilt_run.stage_line({**stage, "at_time_limit": True})


def joint_friction(mu: float):
    """What a model may do once its rock has settled: here, give the block's joint friction ``mu``."""
    def settled() -> None:
        for i in O.interactions:
            if isinstance(i.phys, SmoothJointPhys):
                i.phys.tangensOfFrictionAngle = mu
    return settled


def test_runs_that_differ_only_once_settled_share_the_settled_scene_and_go_on_as_if_each_had_settled_it(
        empty_scene, tmp_path, capsys):
    store = Checkpoint(str(tmp_path / "settled"))
    first = fresh_run(tmp_path / "first", protocol(), settled=joint_friction(0.4), store=store)
    assert first.run() == 23.0 and store.exists()  # tan 21.8 deg: as built
    O.reset()
    shared = saved_run(tmp_path / "shared", protocol(), store.load(), settled=joint_friction(0.5), store=store)
    assert shared.run() == 27.0  # tan 26.6 deg: the joint's friction, given once settled
    assert tilts(shared)[0] == (17.0, "equilibrium") and shared.state["breaks_before_stages"] is not None
    moved = tilting.positions(shared.ids)
    O.reset()
    alone = fresh_run(tmp_path / "alone", protocol(), settled=joint_friction(0.5),
                      store=Checkpoint(str(tmp_path / "own")))
    assert alone.run() == 27.0
    assert np.array_equal(tilting.positions(alone.ids), moved)  # to the last bit


def test_the_settled_scene_is_shared_by_runs_that_differ_only_in_what_is_done_once_settled(tmp_path):
    inputs = {"seed": 1, "friction": 0.2, "out": "a", "resume": -1, "description": "a"}
    store = tilt_run.settled_store(str(tmp_path), inputs, differ_in=("friction",))
    same_rock = {**inputs, "friction": 0.5, "out": "b", "resume": 0, "description": "b"}
    assert tilt_run.settled_store(str(tmp_path), same_rock, ("friction",)).scene_path == store.scene_path
    other_rock = {**inputs, "seed": 2}
    assert tilt_run.settled_store(str(tmp_path), other_rock, ("friction",)).scene_path != store.scene_path
    assert tilt_run.settled_store("", inputs, ("friction",)) is None
