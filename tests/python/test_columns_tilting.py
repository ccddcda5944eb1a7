"""Column layouts of the tilting-table models, staged tilting, checkpoints and monitoring points."""
import json
import math

import numpy as np
import pytest
from yade import O, utils
from yade.wrapper import ParallelBondMat

from conftest import ROCK
from toppling.analyse import failure
from toppling.build import columns, engines
from toppling.build.discs import add_discs, disc
from toppling.load import tilting
from toppling.models import incline
from toppling.run.monitoring import MonitoringPoints, column_top_points
from toppling.run.progress import Progress
from toppling.run.checkpoint import Checkpoint
from toppling.run.steps import run_steps



def test_layout_outline_columns_and_joints():
    layout = columns.ColumnLayout(toe_x=0.15, width=0.05, heights=[0.1, 0.25, 0.2])
    assert [c for p in layout.section() for c in p] == pytest.approx([c for p in [(0.0, 0.0), (0.15, 0.0), (0.15, 0.1), (0.1, 0.1), (0.1, 0.25), (0.05, 0.25),
                                (0.05, 0.2), (0.0, 0.2)] for c in p])
    assert [layout.column_of(x) for x in (0.14, 0.06, 0.01, 0.2, -0.01)] == [1, 2, 3, 0, 0]
    assert layout.main_joints().spacing == 0.05
    assert layout.stacked_blocks(2, 0.04, 0.015) == pytest.approx([0.015, 0.055, 0.095, 0.135, 0.175, 0.215])
    assert layout.stacked_blocks(1, 0.04, 0.0) == pytest.approx([0.04, 0.08])
    cross = layout.cross_joints({k: layout.stacked_blocks(k, 0.04, phase)
                                 for k, phase in ((1, 0.0), (2, 0.015), (3, 0.01))}, block_length=0.04)
    # column 1 stands free downhill: no joints; column 2 leans on column 1 up to 0.1 m, so not at
    # 0.095 (the piece above would touch column 1 over 5 mm < a quarter block); column 3 on 2 up to 0.2 m
    assert sorted(y for _, y in cross.segmentStarts) == pytest.approx([0.01, 0.015, 0.05, 0.055, 0.09, 0.13, 0.17])
    sliver = layout.cross_joints({3: layout.stacked_blocks(3, 0.04, 0.025)}, 0.04)  # 0.185 would leave 1.5 cm on top
    assert sorted(y for _, y in sliver.segmentStarts) == pytest.approx([0.025, 0.065, 0.105, 0.145])
    single = layout.cross_joints({2: [0.03], 3: [0.06]}, block_length=0.04)  # one base joint per column
    assert sorted(y for _, y in single.segmentStarts) == pytest.approx([0.03, 0.06])
    stacked = layout.cross_joints({1: [0.02, 0.09, 0.12], 2: [0.095, 0.24], 3: [0.185]}, 0.04, every_cut=True)
    assert sorted(y for _, y in stacked.segmentStarts) == pytest.approx([0.02, 0.09, 0.095, 0.185, 0.24])
    with pytest.raises(ValueError, match="width"):
        columns.ColumnLayout(0.1, 0.0, [0.1])
    with pytest.raises(ValueError, match="block_length"):
        layout.cross_joints({2: [0.03]}, 0.0)
    with pytest.raises(ValueError, match="phase"):
        layout.stacked_blocks(2, 0.04, 0.05)


def test_profile_layout_has_flat_tops_at_column_centres():
    layout = columns.ColumnLayout.under_profile(0.1, 0.05, 2, lambda d: 2 * d)
    assert layout.heights == pytest.approx([0.05, 0.15])
    assert layout.top_centre(2) == pytest.approx((0.025, 0.15))


def test_points_take_their_column_unless_outside_or_fallen_below_the_floor():
    layout = columns.ColumnLayout(toe_x=0.1, width=0.05, heights=[0.1, 0.3])
    points = np.array([[0.09, 0.05], [0.04, 0.2], [0.12, 0.05], [0.09, -0.02], [-0.01, 0.1]])
    assert list(layout.columns_of(points, floor=-0.01)) == [1, 2, 0, 0, 0]


def test_tilted_layout_height_and_far_edges_follow_the_rotated_outline():
    # two columns 5 cm wide, 0.1 and 0.3 m high, toe at x = 0.1; tilted 30 deg towards the toe
    layout = columns.ColumnLayout(toe_x=0.1, width=0.05, heights=[0.1, 0.3])
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    # H is the crest's: the top centre of the tallest column, 0.075 m behind the toe and 0.3 m up
    # (tilting towards the toe raises it; what lies behind the crest is no part of H)
    assert layout.crest_height(30) == pytest.approx(0.075 * s + 0.3 * c)
    assert layout.far_edges(30) == pytest.approx([0.05 * c - 0.1 * s, 0.10 * c - 0.3 * s])
    assert layout.crest_height(0) == pytest.approx(0.3)
    assert layout.far_edges(0) == pytest.approx([0.05, 0.10])


def test_table_failure_finds_the_hinge_plane_of_toppling_columns_and_ignores_discs_off_the_table():
    """Six columns 0.3 m high; columns 1-4 rotate about hinges on a plane rising into the slope
    at phi = 15 deg from 2 cm above the toe (displacement zero below the hinge, growing above
    it), columns 5-6 stay put, and a disc that had already dropped below the table falls on."""
    layout = columns.ColumnLayout(toe_x=0.3, width=0.05, heights=[0.3] * 6)
    hinge = {k: 0.02 + math.tan(math.radians(15)) * (k - 0.5) * 0.05 for k in range(1, 5)}
    reference, disp, tops = [], [], {}
    for k in range(1, 7):
        centre = layout.top_centre(k)[0]
        for y in np.arange(0.001, 0.3, 0.002):
            for dx in (-0.01, 0.0, 0.01):
                reference.append((centre + dx, y))
                disp.append((0.001 + 0.05 * (y - hinge[k]), 0.0) if k in hinge and y > hinge[k] else (0.0, 0.0))
        tops[failure.column_label(k)] = len(reference) - 2  # the top disc at the column's centre
    reference.append((layout.top_centre(1)[0], -0.05))  # off the table before the last equilibrium
    disp.append((0.0, -1.0))
    reference = np.array(reference)
    result = failure.table_failure(layout, reference, reference + np.array(disp), tops,
                                    lambda label: label in ("A-1", "B-2", "C-3", "D-4"), np.zeros((0, 2)), 30.0,
                                    floor=-0.01, band=0.01, least_motion=1e-5)
    assert [p.phi_deg for p in result["planes"]] == [pytest.approx(15.0, abs=0.5)]
    assert result["overall"] == result["planes"][0]  # one plane: the overall surface is it
    assert result["split_p"] is None  # four failure points: no split into two lines of >= 3
    assert result["zones"] == ["toppling"] * 4 + ["no-movement"] * 2
    assert result["t_over_h"] == pytest.approx(layout.far_edges(30.0)[3] / layout.crest_height(30.0))


@pytest.mark.parametrize("tilt, expected", [(16.0, "equilibrium"), (27.0, "failed")])
def test_stage_ends_in_equilibrium_below_and_fails_above_the_joint_friction(empty_scene, tilt, expected):
    setup = incline.build(0.1, 0.05, 0.012 / 2.5, 0.012, ROCK, math.degrees(math.atan(0.4)))  # 21.8 deg
    engines.set_local_damping(0.5)
    watched = [setup.block]
    criteria = tilting.StageCriteria(chunk=0.02, rest_speed=1e-3, fail_displacement=2e-3, max_stage_time=0.3)
    assert tilting.run_stage(tilt, watched, tilting.medians(watched), criteria) == expected


@pytest.mark.parametrize("fail_columns, expected", [(1, "failed"), (2, "equilibrium")])
def test_a_lone_group_gone_fails_the_stage_only_if_fail_columns_is_one(empty_scene, fail_columns, expected):
    """The block slides off at 27 deg and the base stays put: with fail_columns 2 the block is
    gone and the base, at rest, decides."""
    setup = incline.build(0.1, 0.05, 0.012 / 2.5, 0.012, ROCK, math.degrees(math.atan(0.4)))  # 21.8 deg
    engines.set_local_damping(0.5)
    watched = [setup.block, setup.base]
    criteria = tilting.StageCriteria(chunk=0.02, rest_speed=1e-3, fail_displacement=2e-3, max_stage_time=0.3,
                                     fail_columns=fail_columns)
    reference = tilting.medians(watched)
    assert tilting.run_stage(27.0, watched, reference, criteria) == expected
    assert list(tilting.gone(tilting.medians(watched), reference, criteria)) == [True, False]


def test_a_corner_breaking_off_a_column_top_is_not_the_column_gone(empty_scene):
    """Line 288's 15 deg stage: five of B-2's seventeen top discs broke off and fell off the table
    while the rest stood; their mean passed fail_displacement as if the column had toppled off."""
    top = _column_top(0.0, 5)
    criteria = tilting.StageCriteria(fail_displacement=0.05)
    reference = tilting.medians([top])
    _lower(top[:2], 0.8)  # their mean drops 0.32 m
    assert not tilting.gone(tilting.medians([top]), reference, criteria)[0]
    _lower(top[2:], 0.06)  # the rest of the top goes too
    assert tilting.gone(tilting.medians([top]), reference, criteria)[0]


def _column_top(x: float, count: int) -> list[int]:
    """``count`` rock discs in a row from ``x``, 0.3 m up: a column's top band."""
    return [O.bodies.append(disc((x + 0.01 * k, 0.3), 0.004, ParallelBondMat(**ROCK))) for k in range(count)]


def _lower(ids: list[int], dy: float) -> None:
    for i in ids:
        O.bodies[i].state.pos = O.bodies[i].state.pos - (0, dy, 0)


def _along_slope_response(load) -> tuple[float, float]:
    """(peak, static) displacement along the table of a block on a joint under ``load``."""
    setup = incline.build(0.1, 0.05, 0.012 / 2.5, 0.012, ROCK, math.degrees(math.atan(0.4)))
    incline.settle(0.02)  # at rest under upright gravity

    def centre() -> float:
        return float(tilting.positions(setup.block)[:, 0].mean())

    start, peak = centre(), 0.0
    load()
    for _ in range(200):
        run_steps(5)
        peak = max(peak, centre() - start)
    incline.settle(0.05)
    return peak, centre() - start


def test_ramped_tilt_loads_statically_and_a_sudden_tilt_twice(empty_scene):
    """A step load overshoots its static response by a factor 2 (undamped single degree of
    freedom); the same tilt applied over many periods (~9 ms here) does not."""
    tilt = 10.0  # well below the joint's 21.8 deg: elastic
    ramp_peak, static = _along_slope_response(lambda: tilting.ramp(0.0, tilt, 0.05))
    assert ramp_peak / static == pytest.approx(1.0, abs=0.05)
    assert tilting.current_tilt() == pytest.approx(tilt)
    O.reset()
    jump_peak, _ = _along_slope_response(lambda: tilting.set_tilt(tilt))
    assert jump_peak / static == pytest.approx(2.0, abs=0.15)


@pytest.mark.parametrize("moved_mm, elapsed, expected", [(0.6, 2.1, "equilibrium"), (2.3, 2.1, "failed"),
                                                        (0.6, 1.9, None)])
def test_at_the_time_limit_a_group_ringing_in_place_is_at_rest_and_one_creeping_fails(moved_mm, elapsed, expected):
    """Two groups, one at rest; the other moves 0.05 mm per 0.02 s chunk (2.5 mm/s, above
    rest_speed 1 mm/s) and is ``moved_mm`` from where the stage began: after the 2 s limit
    it creeps if its mean speed over the stage (moved / elapsed) is above rest_speed, and rings
    in place if below; before the limit the stage goes on."""
    criteria = tilting.StageCriteria(chunk=0.02, rest_speed=1e-3, fail_displacement=0.05, max_stage_time=2.0)
    reference = np.zeros((2, 2))
    now = np.array([[0.0, 0.0], [1e-3 * moved_mm, 0.0]])
    before = now - [[0.0, 0.0], [0.0, 5e-5]]
    assert tilting.stage_outcome(now, before, reference, elapsed, criteria) == expected


def test_a_stage_ends_at_rest_or_when_enough_groups_are_gone_whatever_the_time():
    criteria = tilting.StageCriteria(chunk=0.02, rest_speed=1e-3, fail_displacement=0.05, max_stage_time=2.0,
                                     fail_columns=2)
    reference = np.zeros((3, 2))
    one_gone = np.array([[0.0, 0.0], [0.0, 0.0], [0.08, 0.0]])
    assert tilting.stage_outcome(one_gone, one_gone, reference, 0.1, criteria) == "equilibrium"  # the rest at rest
    two_gone = np.array([[0.06, 0.0], [0.0, 0.0], [0.08, 0.0]])
    assert tilting.stage_outcome(two_gone, one_gone, reference, 0.1, criteria) == "failed"
    # fewer groups left than fail_columns (the others toppled off alone in earlier stages): all of them
    assert tilting.stage_outcome(one_gone[2:], one_gone[2:], reference[2:], 0.1, criteria) == "failed"
    assert tilting.stage_outcome(one_gone[1:2], one_gone[1:2], reference[1:2], 0.1, criteria) == "equilibrium"


def test_resumed_ramp_and_stage_continue_from_their_start(empty_scene):
    """A run resumed from a checkpoint in the middle of a ramp or a stage passes the time the
    ramp or stage began: the ramp goes on from where it was, the stage's time limit counts."""
    setup = incline.build(0.1, 0.05, 0.012 / 2.5, 0.012, ROCK, math.degrees(math.atan(0.4)))  # 21.8 deg
    incline.settle(0.02)
    resumed_at = O.time
    tilting.ramp(0.0, 10.0, 0.05, start=resumed_at - 0.03)  # 30 ms into a 50 ms ramp
    assert O.time - resumed_at == pytest.approx(0.02, abs=1.5e-3)
    assert tilting.current_tilt() == pytest.approx(10.0)
    # sliding at 27 deg, never 1 m: only the time limit can end the stage, which began 0.3 s ago
    criteria = tilting.StageCriteria(chunk=0.01, rest_speed=1e-3, fail_displacement=1.0, max_stage_time=0.3)
    resumed_at = O.time
    watched = [setup.block]
    began_at = tilting.medians(watched) - [0.01, 0.0]  # the block slid 1 cm since the stage began
    assert tilting.run_stage(27.0, watched, began_at, criteria, start=O.time - 0.3) == "failed"
    assert O.time - resumed_at == pytest.approx(criteria.chunk, rel=0.05)


def test_a_resumed_stage_judges_rest_over_the_window_its_checkpoint_kept(empty_scene):
    """A stage's watch lives in a list the run checkpoints (as JSON): resumed with it, a stage at
    rest is judged after one chunk, as the uninterrupted stage would be; started afresh it waits a
    whole rest window."""
    setup = incline.build(0.1, 0.05, 0.012 / 2.5, 0.012, ROCK, 40.0)
    incline.settle(0.02)
    watched = [setup.block]
    criteria = tilting.StageCriteria(chunk=0.01, rest_speed=1e-3, fail_displacement=1.0, max_stage_time=1.0,
                                     rest_window=0.05)
    kept = json.loads(json.dumps([tilting.medians(watched).tolist()] * criteria.window_chunks))
    for history, chunks in ((kept, 1), (None, criteria.window_chunks)):
        began = O.time
        reference = tilting.medians(watched)
        assert tilting.run_stage(0.0, watched, reference, criteria, history=history) == "equilibrium"
        assert O.time - began == pytest.approx(chunks * criteria.chunk, rel=0.05)
    assert len(kept) == criteria.window_chunks + 1  # the window and the chunk now, no more


def test_column_top_points_are_the_discs_nearest_the_tops_and_skip_an_empty_column(empty_scene, capsys):
    layout = columns.ColumnLayout(toe_x=0.15, width=0.05, heights=[0.1, 0.25, 0.2])
    discs = {(0.075, 0.24): "top of B-2", (0.075, 0.1): "", (0.03, 0.15): "", (0.02, 0.18): "top of C-3"}
    names = {O.bodies.append(utils.sphere((x, y, 0), 0.005)): name for (x, y), name in discs.items()}
    points = column_top_points(layout, list(names))
    assert points.labels == ["B-2", "C-3"]
    assert [names[i] for i in points.ids] == ["top of B-2", "top of C-3"]
    assert "column A-1: no discs" in capsys.readouterr().out


def test_checkpoint_resumes_scene_and_driver_state(empty_scene, tmp_path):
    setup = incline.build(0.1, 0.05, 0.012 / 2.5, 0.012, ROCK, 20.0)
    points = MonitoringPoints(["A-1"], [setup.toe])
    run_steps(50)
    points.record()
    checkpoint = Checkpoint(str(tmp_path))
    assert not checkpoint.exists()
    checkpoint.save({"tilt": 12.5, "points": points.as_dict()})
    iteration, position = O.iter, tuple(O.bodies[setup.toe].state.pos)
    O.reset()
    state = checkpoint.load()
    assert state["tilt"] == 12.5 and O.iter == iteration
    assert tuple(O.bodies[setup.toe].state.pos) == position
    restored = MonitoringPoints.from_dict(json.loads(json.dumps(state["points"])))
    restored.record()
    assert len(restored.time) == 2 and restored.total("A-1")[0] == pytest.approx(points.total("A-1")[0])


def test_same_command_continues_its_own_checkpoint_and_no_other(empty_scene, tmp_path):
    checkpoint = Checkpoint(str(tmp_path))
    run = {"rmin": 0.001, "arrangement": "ideal", "max_tilt": 45.0}
    assert not checkpoint.continues(run, resume=-1)  # nothing to continue
    checkpoint.save({"inputs": run})
    assert checkpoint.continues(dict(run), resume=-1)
    assert checkpoint.continues({**run, "max_tilt": 60.0}, resume=-1, free=("max_tilt",))
    with pytest.raises(ValueError, match=r"other parameters \(rmin 0.001 there, 0.002 here\): resume=0 starts"):
        checkpoint.continues({**run, "rmin": 0.002}, resume=-1, free=("max_tilt",))  # keeps the other run's results
    assert checkpoint.continues({**run, "rmin": 0.002}, resume=1) and not checkpoint.continues(run, resume=0)
    with pytest.raises(ValueError, match="resume = 2"):
        checkpoint.continues(run, resume=2)


def test_missing_checkpoint_says_what_to_do(tmp_path):
    with pytest.raises(FileNotFoundError, match="without resume"):
        Checkpoint(str(tmp_path)).load()


def test_bad_stage_criteria_are_refused():
    with pytest.raises(ValueError, match="rest_speed"):
        tilting.StageCriteria(rest_speed=0)
    with pytest.raises(ValueError, match="fail_columns"):
        tilting.StageCriteria(fail_columns=1.5)
    with pytest.raises(ValueError, match="duration"):
        tilting.ramp(0.0, 10.0, 0.0)


def test_progress_eta_of_a_phase_of_known_length_is_its_remaining_time_at_the_current_rate(
        empty_scene, monkeypatch, capsys):
    O.engines = engines.engines(timestepper=False)
    wall = iter([100.0, 100.0, 110.0])  # Progress() at 100 s, lines at 100 s and 110 s
    monkeypatch.setattr("toppling.run.progress.time.time", lambda: next(wall))
    progress = Progress(every=5.0, energy=lambda: 1.25e-3)
    progress("post", remaining_time=0.3)  # no rate yet
    O.dt = 0.01
    run_steps(2)  # 0.02 simulated s in 10 wall s: 0.1 s more take 50 s
    progress("post", remaining_time=0.1)
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].endswith("ETA ?") and lines[1].endswith("ETA 50 s")
    assert "Ek = 1.250e-03 J" in lines[0]  # the energy it was given


def test_progress_gives_the_wall_time_to_a_stage_s_time_limit_at_the_current_rate(empty_scene, monkeypatch, capsys):
    """A stage ringing towards its time limit: the ETA to max_tilt cannot see its end, its bound can."""
    O.engines = engines.engines(timestepper=False)
    wall = iter([100.0, 100.0, 110.0])
    monkeypatch.setattr("toppling.run.progress.time.time", lambda: next(wall))
    progress = Progress(every=5.0, energy=lambda: 0.0)
    progress("stage", fraction_done=0.5, stage_bound=1.0)  # no rate yet
    O.dt = 0.01
    run_steps(2)  # 0.02 simulated s in 10 wall s: 1.5 s more take 750 s
    progress("stage", fraction_done=0.5, stage_bound=1.5)
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].endswith("ETA ?") and lines[1].endswith("ETA ? (this stage ends within 750 s)")


def test_progress_eta_of_a_resumed_run_counts_only_the_work_done_in_this_process(empty_scene, monkeypatch, capsys):
    """Resumed halfway (the earlier process did half the work): the quarter done in this one took
    100 s, so the quarter left takes 100 s, not the 20 s that half-done-in-120-s would say."""
    O.engines = engines.engines(timestepper=False)
    wall = iter([0.0, 20.0, 120.0])  # Progress() at 0 s, lines at 20 s and 120 s
    monkeypatch.setattr("toppling.run.progress.time.time", lambda: next(wall))
    progress = Progress(every=5.0, energy=lambda: 0.0)
    progress("stage", fraction_done=0.5)
    progress("stage", fraction_done=0.75)
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].endswith("ETA ?") and lines[1].endswith("ETA 100 s")


def test_rate_since_is_the_change_of_total_displacement_per_second():
    points = MonitoringPoints.from_dict({"labels": ["A-1"], "ids": [0], "reference": [(0, 0, 0)],
                                                 "time": [0.0, 1.0, 2.0, 3.0],
                                                 "x": {"A-1": [0.0, 0.03, 0.03, 0.09]},
                                                 "y": {"A-1": [0.0, 0.04, 0.04, 0.12]}})
    assert points.rate_since("A-1", 1.1) == pytest.approx(0.05)  # 0.05 m to 0.15 m over 1 s to 3 s
    assert points.rate_since("A-1", 3.0) == 0.0


def test_direction_is_the_total_displacement_s_y_over_x_once_the_point_has_moved():
    """Y/X of the displacement since the start (the last step's own dY/dX, -1, would be noise
    at rest); none while the point has moved less than ``still`` (a ringing top)."""
    points = MonitoringPoints.from_dict({"labels": ["G-7"], "ids": [0], "reference": [(0, 0, 0)],
                                                 "time": [0.0, 0.1, 0.2, 0.3],
                                                 "x": {"G-7": [0.0, 2e-6, 1e-3, 2e-3]},
                                                 "y": {"G-7": [0.0, -3e-6, 0.0, -1e-3]}})
    direction = points.direction("G-7", still=1e-4)
    assert all(math.isnan(d) for d in direction[:2])
    assert direction[2:] == [0.0, -0.5]


def test_kinetic_energy_above_the_floor_leaves_out_a_disc_fallen_below_it(empty_scene):
    """Closed form: 1/2 m v^2 + 1/2 I w^2 of the discs above the floor, the scene's total when
    none is below it; the progress line prints that energy."""
    up, down = add_discs([(0, 0.1, 0.01), (0, -0.1, 0.01)], ParallelBondMat(**ROCK))
    for i, (v, w) in zip((up, down), ((0.3, 2.0), (5.0, 0.0))):
        O.bodies[i].state.vel, O.bodies[i].state.angVel = (v, 0, 0), (0, 0, w)
    s = O.bodies[up].state
    expected = 0.5 * s.mass * 0.3 ** 2 + 0.5 * s.inertia[2] * 2.0 ** 2
    assert tilting.kinetic_energy_above([up, down], floor=0.0) == pytest.approx(expected, rel=1e-12)
    assert tilting.kinetic_energy_above([up, down], floor=-1.0) == pytest.approx(utils.kineticEnergy(), rel=1e-12)


@pytest.mark.parametrize("floor, expected", [(0.0, 0.101), (-10.0, None)])
def test_a_failure_comes_to_rest_once_what_moves_has_dropped_off_the_table(empty_scene, floor, expected):
    """A disc at rest and one falling freely from 5 cm: judged until it drops below ``floor``
    (0.101 s = sqrt(2 h / g)), after which the disc at rest alone decides; with a floor it never
    reaches, the failure is still moving at the time limit (None)."""
    still, falling = (O.bodies.append(utils.sphere((x, 0.05, 0), 0.005, fixed=fixed))
                      for x, fixed in ((0.0, True), (0.1, False)))
    O.engines = engines.engines()
    O.dt = 1e-5
    criteria = tilting.StageCriteria(chunk=0.01, rest_speed=1e-3)
    came_to_rest = tilting.run_arrest([[still], [falling]], floor, criteria, arrest_time=0.3)
    if expected is None:
        assert came_to_rest is None and O.time == pytest.approx(0.3, abs=criteria.chunk)
    else:  # it rests at the end of the first chunk that starts with the disc below the floor
        assert expected <= came_to_rest <= expected + 2 * criteria.chunk
    with pytest.raises(ValueError, match="arrest_time = 0"):
        tilting.run_arrest([[still]], floor, criteria, arrest_time=0)


def test_rest_is_judged_over_the_rest_window():
    # A standing, undamped slope rings: a median 0.1 mm from where it was one window ago moves at
    # 5 mm/s over one chunk but 0.5 mm/s over a 0.2 s window.
    windowed = tilting.StageCriteria(chunk=0.02, rest_speed=1e-3, fail_displacement=0.05, max_stage_time=2.0,
                                     rest_window=0.2)
    assert windowed.window_chunks == 10
    start, now = np.zeros((1, 2)), np.array([[1e-4, 0.0]])
    assert tilting.stage_outcome(now, start, start, 1.0, windowed) == "equilibrium"
    assert tilting.stage_outcome(now, None, start, 1.0, windowed) is None  # the stage is younger than a window
    one_chunk = tilting.StageCriteria(chunk=0.02, rest_speed=1e-3, fail_displacement=0.05, max_stage_time=2.0)
    assert tilting.stage_outcome(now, start, start, 1.0, one_chunk) is None
    with pytest.raises(ValueError, match="rest_window = 0.01 is invalid"):
        tilting.StageCriteria(chunk=0.02, rest_window=0.01)
