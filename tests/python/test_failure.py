"""Failure analysis on synthetic displacement fields and crack sets with known answers."""
import math

import numpy as np
import pytest

from toppling.analyse import failure

WIDTH = 0.05  # column width [m]


def columns_cut_by(surface, n_columns=12, height=0.5, spacing=0.004):
    """Disc centres of columns 1..n (toe at x = 0, slope towards -x); discs above
    ``surface(x)`` rotated rigidly about the column's failure point, the rest still."""
    pos, disp, column = [], [], []
    for k in range(1, n_columns + 1):
        xc = -(k - 0.5) * WIDTH
        cut = surface(xc)
        for x in np.arange(xc - 0.02, xc + 0.021, spacing):
            for y in np.arange(0.0, height, spacing):
                pos.append((x, y))
                column.append(k)
                if y > cut:  # topple by 2 degrees about (xc, cut)
                    a = math.radians(-2)
                    rx, ry = x - xc, y - cut
                    disp.append((rx * math.cos(a) - ry * math.sin(a) - rx, rx * math.sin(a) + ry * math.cos(a) - ry))
                else:
                    disp.append((0.0, 0.0))
    return np.array(pos), np.array(disp), np.array(column)


def surface_points(pos, disp, column, **kw):
    points = []
    for k in sorted(set(column)):
        sel = column == k
        p = failure.failure_point(pos[sel], disp[sel], moved_threshold=1e-5, **kw)
        if p:
            points.append(p)
    return points


def test_single_failure_surface_at_15_degrees():
    tan = math.tan(math.radians(15))
    pos, disp, column = columns_cut_by(lambda x: 0.02 - tan * x)
    planes = failure.fit_failure_surface(surface_points(pos, disp, column))
    assert len(planes) == 1
    assert planes[0].phi_deg == pytest.approx(15, abs=0.5)


def points_on_two_surfaces():
    """Failure points of 14 columns cut at 14 degrees over the six at the toe, 24 above."""
    t1, t2, xb = math.tan(math.radians(14)), math.tan(math.radians(24)), -6 * WIDTH
    surface = lambda x: 0.02 - t1 * x if x > xb else 0.02 - t1 * xb - t2 * (x - xb)  # noqa: E731
    return surface_points(*columns_cut_by(surface, n_columns=14))


def noisy_straight_points():
    """12 failure points on a 20 degree line, scattered by 4 mm."""
    x = -np.arange(1, 13) * WIDTH
    return list(zip(x, 0.02 - math.tan(math.radians(20)) * x + np.random.default_rng(3).normal(0, 0.004, len(x))))


def test_two_failure_surfaces_14_and_24_degrees():
    planes = failure.fit_failure_surface(points_on_two_surfaces())
    assert [round(p.phi_deg) for p in planes] == [14, 24]


def test_noisy_straight_surface_stays_one_plane():
    planes = failure.fit_failure_surface(noisy_straight_points())
    assert len(planes) == 1
    assert planes[0].phi_deg == pytest.approx(20, abs=2)


def test_the_overall_surface_is_one_line_through_a_dog_leg_that_splits_into_two():
    """A toe segment along the table (four points at y = 0) and a 45 degree one above it: the
    fit splits them, the overall surface is their least-squares line, slope 25/42 by hand
    (k = 0..7 columns in from the toe, y_k = max(0, k - 3) widths)."""
    points = [(-k * WIDTH, max(0, k - 3) * WIDTH) for k in range(8)]
    assert [p.phi_deg for p in failure.fit_failure_surface(points)] == pytest.approx([0.0, 45.0], abs=1e-9)
    assert failure.overall_surface(points).phi_deg == pytest.approx(math.degrees(math.atan(25 / 42)), abs=1e-9)
    straight = noisy_straight_points()
    assert failure.overall_surface(straight) == failure.fit_failure_surface(straight)[0]  # one plane: the same line
    with pytest.raises(ValueError, match="1 failure points: a failure surface needs at least 2"):
        failure.overall_surface(points[:1])


def test_cracks_refine_the_failure_point():
    pos, disp, column = columns_cut_by(lambda x: 0.1, n_columns=1)
    cracks = np.array([(-0.025, 0.105), (-0.02, 0.103), (-0.03, 0.107), (0.5, 0.3)])  # last: other column
    x, y = failure.failure_point(pos, disp, 1e-5, cracks=cracks, band=0.01)
    assert y == pytest.approx(0.105)
    assert x == pytest.approx(-0.025, abs=1e-3)


def test_hinge_of_a_rotating_column_under_elastic_noise():
    """A column toppling 2 degrees about a hinge at 0.1 m, every disc also jittered by up to
    0.2 mm (elastic response): the failure point is the hinge, not where the displacement
    passes a threshold (a fifth of the top's 14 mm would put it at 0.18 m)."""
    pos, disp, _ = columns_cut_by(lambda x: 0.1, n_columns=1)
    disp = disp + np.random.default_rng(5).uniform(-2e-4, 2e-4, disp.shape)
    top = np.linalg.norm(disp, axis=1).max()
    _, y = failure.failure_point(pos, disp, moved_threshold=0.2 * top)
    assert y == pytest.approx(0.1, abs=0.004)  # the disc spacing


def test_failure_point_of_a_sliding_part_is_its_base():
    pos = np.array([(0.0, y) for y in np.linspace(0, 0.3, 61)])
    disp = np.where(pos[:, 1:] > 0.17, [[0.01, 0.0]], [[0.0, 0.0]])  # the part above 0.17 m slid 1 cm
    _, y = failure.failure_point(pos, disp, moved_threshold=1e-3)
    assert y == pytest.approx(0.1725)  # between the discs at 0.170 and 0.175


def test_unmoved_column_has_no_failure_point():
    pos = np.array([(0.0, y) for y in np.linspace(0, 0.3, 20)])
    assert failure.failure_point(pos, np.zeros_like(pos), 1e-5) is None


def test_rotation_of_a_rigidly_turned_point_set():
    rng = np.random.default_rng(1)
    p = rng.random((50, 2))
    a = math.radians(7)
    q = p @ np.array([[math.cos(a), math.sin(a)], [-math.sin(a), math.cos(a)]]) + (0.3, -0.1)
    assert failure.rotation_deg(p, q) == pytest.approx(7)


def test_slope_frame_of_tilted_joints():
    # joints dipping 55 degrees: a point one unit up the joint from the toe is at (0, 1)
    a = math.radians(55)
    local = failure.slope_frame(np.array([(1 + math.cos(a), 2 + math.sin(a))]), (1, 2), 55)
    assert local[0] == pytest.approx((0, 1))


def test_zones_and_normalised_distances():
    zones = [failure.zone(*c, still=1e-4) for c in [
        (0.05, True, 0.04),  # toe column slides
        (0.03, True, 0.001),  # topples
        (0.02, True, 0.001),  # topples
        (0.002, False, 0.0),  # moved, at rest
        (0.0, False, 0.0)]]
    assert zones == ["sliding", "toppling", "toppling", "stable", "no-movement"]
    d = failure.zone_distances(zones, far_edges=[0.1, 0.2, 0.3, 0.4, 0.5], height=0.5)
    assert d == {"t_over_h": pytest.approx(0.6), "s_over_h": pytest.approx(0.8)}


def test_a_column_without_discs_counts_for_neither_distance():
    d = failure.zone_distances(["toppling", "stable", "empty"], far_edges=[0.1, 0.2, 0.3], height=0.5)
    assert d == {"t_over_h": pytest.approx(0.2), "s_over_h": pytest.approx(0.4)}


def test_column_failure_gives_zones_and_the_failure_points_of_the_failing_columns():
    """Columns toppling above a 15 deg surface, one without a top point, one come to rest, three
    unmoved, and a disc off the table falling 7 m (column 0): zones as built, the surface found."""
    tan = math.tan(math.radians(15))
    pos, disp, column = columns_cut_by(lambda x: 0.02 - tan * x)
    disp[column >= 10] = 0.0
    pos, disp, column = np.vstack([pos, [(0.01, -0.1)]]), np.vstack([disp, [(0.0, -7.0)]]), np.append(column, 0)
    tops = [int(np.flatnonzero(column == k)[np.argmax(pos[column == k, 1])]) for k in range(1, 13)]
    tops[2] = None
    moving = [k != 9 for k in range(1, 13)]
    zones, points = failure.column_failure(pos, disp, column, tops, moving, cracks=None, band=0.008)
    assert zones == ["toppling"] * 2 + ["empty"] + ["toppling"] * 5 + ["stable"] + ["no-movement"] * 3
    assert len(points) == 7
    planes = failure.fit_failure_surface(points)
    assert len(planes) == 1 and planes[0].phi_deg == pytest.approx(15, abs=0.5)


def test_a_column_fallen_off_the_table_does_not_make_the_moved_ones_unmoved():
    """Toe column dropped 0.8 m off the table, the next two toppled 10 mm: 2 % of the fall
    (16 mm) would call them unmoved; they are toppling, the unmoved ones stay unmoved, and
    below ``least_motion`` a move does not count."""
    pos, disp, column = columns_cut_by(lambda x: 0.02, n_columns=5)
    disp[column >= 4] = 0.0
    top = [int(np.flatnonzero(column == k)[np.argmax(pos[column == k, 1])]) for k in range(1, 6)]
    disp[column == 1] = (0.0, -0.8)
    disp[column == 2] *= 0.010 / np.linalg.norm(disp[top[1]])
    disp[column == 3] *= 0.010 / np.linalg.norm(disp[top[2]])
    moving = [True] * 3 + [False] * 2
    kept, _ = failure.column_failure(pos, disp, column, top, moving, cracks=None, band=0.008)
    assert kept == ["sliding"] + ["no-movement"] * 4  # the fall sets the scale
    zones, points = failure.column_failure(pos, disp, column, top, moving, cracks=None, band=0.008,
                                            fell_off=[True] + [False] * 4)
    assert zones == ["sliding", "toppling", "toppling", "no-movement", "no-movement"]
    assert [y for _, y in points[1:]] == [pytest.approx(0.02, abs=0.004)] * 2  # one disc spacing
    coarse, _ = failure.column_failure(pos, disp, column, top, moving, cracks=None, band=0.008,
                                        fell_off=[True] + [False] * 4, least_motion=0.015)
    assert coarse == ["sliding"] + ["no-movement"] * 4  # 10 mm is below the model's resolution
    with pytest.raises(ValueError, match="least_motion"):
        failure.column_failure(pos, disp, column, top, moving, cracks=None, band=0.008, least_motion=-1.0)
    with pytest.raises(ValueError, match="fell_off"):
        failure.column_failure(pos, disp, column, top, moving, cracks=None, band=0.008, fell_off=[True])


def test_column_labels_follow_the_thesis():
    assert [failure.column_label(k) for k in (1, 7, 15, 26, 27)] == ["A-1", "G-7", "O-15", "Z-26", "AA-27"]
    with pytest.raises(ValueError, match="column"):
        failure.column_label(0)


def sse_of_line(x, y):
    return float(np.sum((y - np.polyval(np.polyfit(x, y, 1), x)) ** 2))


def test_the_split_p_value_is_exact_where_only_one_split_is_possible():
    """Six points admit one split (3 + 3), where the F-test is exact: p = SSE2 / SSE1 (F(2, 2)),
    which the Monte Carlo p matches to its resolution, and of straight lines with noise 5 % have
    p < 0.05."""
    rng = np.random.default_rng(11)
    x = -np.arange(1, 7) * WIDTH
    lines = [0.3 * x + rng.normal(0, 0.004, 6) for _ in range(4000)]
    p = np.array([failure.split_p_value(list(zip(x, y))) for y in lines])
    exact = np.array([(sse_of_line(x[:3], y[:3]) + sse_of_line(x[3:], y[3:])) / sse_of_line(x, y) for y in lines])
    assert np.max(np.abs(p - exact)) < 0.03  # 4000 draws: their CDF is off by under 0.022 for 95 % of seeds
    assert np.mean(p < 0.05) == pytest.approx(0.05, abs=0.012)


def test_the_split_p_value_tells_two_surfaces_from_one():
    assert failure.split_p_value(points_on_two_surfaces()) < 1e-3
    noisy = noisy_straight_points()
    assert failure.split_p_value(noisy) > 0.05
    assert failure.split_p_value(noisy[:5]) is None


def test_the_split_p_value_holds_its_level_where_the_break_is_searched_for():
    """Ten points admit five splits: of straight lines with noise, 5 % have p < 0.05 (the
    F-test's p, which takes the best split as given, gives 18 %), and the fit calls no line
    with p >= 0.05 two planes."""
    rng = np.random.default_rng(12)
    x = -np.arange(1, 11) * WIDTH
    lines = [list(zip(x, 0.3 * x + rng.normal(0, 0.004, 10))) for _ in range(1000)]
    p = np.array([failure.split_p_value(q) for q in lines])
    assert np.mean(p < 0.05) == pytest.approx(0.05, abs=0.02)
    assert all(len(failure.fit_failure_surface(q)) == 1 for q, pq in zip(lines, p) if pq >= 0.05)
    with pytest.raises(ValueError, match="alpha = 1.5: .* between 0 and 1"):
        failure.fit_failure_surface(lines[0], alpha=1.5)
    with pytest.raises(ValueError, match="draws = 0"):
        failure.split_p_value(lines[0], draws=0)


def two_surface_heights(x: np.ndarray) -> np.ndarray:
    """14 degrees over the five columns at the toe, 24 above (the thesis' random model)."""
    t1, t2, xb = math.tan(math.radians(14)), math.tan(math.radians(24)), -5 * WIDTH
    return np.where(x > xb, -t1 * x, -t1 * xb - t2 * (x - xb))


def test_the_pooled_split_p_value_of_one_run_is_its_split_p_value():
    rng = np.random.default_rng(4)
    x = -np.arange(1, 11) * WIDTH
    for run in (list(zip(x, two_surface_heights(x) + rng.normal(0, 0.01, 10))), noisy_straight_points()):
        assert failure.pooled_split_p_value([run, run[:1]]) == failure.split_p_value(run)
        cut, lines = failure.pooled_split([run, run[:1]])
        assert lines[1] is None and lines[0] is not None  # one entry per run, in order
    assert failure.pooled_split_p_value([noisy_straight_points()[:5]] * 3) is None
    assert failure.pooled_split([noisy_straight_points()[:5]] * 3) is None
    with pytest.raises(ValueError, match="draws = 0"):
        failure.pooled_split_p_value([noisy_straight_points()], draws=0)


def test_a_break_too_weak_to_show_in_one_run_shows_in_six():
    """Six runs on the same two surfaces, scattered by 1 cm: most runs alone fall short of two
    planes at 5 %, the six together do not, and their common cut is the break."""
    rng = np.random.default_rng(3)
    x = -np.arange(1, 11) * WIDTH + WIDTH / 2
    runs = [list(zip(x, two_surface_heights(x) + rng.normal(0, 0.01, 10))) for _ in range(6)]
    assert sum(failure.split_p_value(run) >= 0.05 for run in runs) >= 4
    assert failure.pooled_split_p_value(runs) < 0.01
    cut, lines = failure.pooled_split(runs)
    assert -7 * WIDTH < cut < -3 * WIDTH  # within a column of the break (-5 widths: between columns 5 and 6)
    assert len(lines) == 6
    assert np.mean([toe.phi_deg for toe, _ in lines]) == pytest.approx(14, abs=3)
    assert np.mean([upper.phi_deg for _, upper in lines]) == pytest.approx(24, abs=3)


def test_the_pooled_cuts_fall_between_columns_so_rounding_to_the_mm_moves_neither_cut_nor_p():
    """Runs' failure points of one column lie millimetres apart; a cut between them would part
    one column's points of different runs, and rounding would add or drop such cuts (the record
    in docs/tilting_table.md keeps points to the mm). Five sets of eight runs on the thesis'
    two surfaces, scattered by 2 mm in x and 2 cm in y."""
    x = -np.arange(1, 11) * WIDTH
    for seed in range(5, 10):
        rng = np.random.default_rng(seed)
        runs = [list(zip(x + rng.normal(0, 0.002, 10), two_surface_heights(x) + rng.normal(0, 0.02, 10)))
                for _ in range(8)]
        rounded = [[(round(a, 3), round(b, 3)) for a, b in run] for run in runs]
        assert len(failure._cuts([np.array(run)[:, 0] for run in runs])) == 9  # one between each pair of columns
        assert failure.pooled_split(rounded)[0] == pytest.approx(failure.pooled_split(runs)[0], abs=0.001)
        assert failure.pooled_split_p_value(rounded) == pytest.approx(failure.pooled_split_p_value(runs), abs=0.01)


def test_the_pooled_split_p_value_holds_its_level_over_runs_with_lines_of_their_own():
    """Four runs of eight points, each a straight line of its own slope, height and scatter
    (2 to 20 mm) at x of its own: of 1000 such sets 5 % have p < 0.05. Were the runs' lines
    pooled into one, their different slopes would read as a break; were their residuals
    summed, the most scattered run would decide alone."""
    rng = np.random.default_rng(7)
    xs = [-np.arange(1, 9) * WIDTH + rng.normal(0, 0.002, 8) for _ in range(4)]
    p = np.array([failure.pooled_split_p_value([list(zip(x, rng.normal(0.02, 0.01) - rng.uniform(0, 1) * x
                                                               + rng.normal(0, rng.uniform(0.002, 0.02), 8)))
                                                 for x in xs])
                  for _ in range(1000)])
    assert np.mean(p < 0.05) == pytest.approx(0.05, abs=0.02)
