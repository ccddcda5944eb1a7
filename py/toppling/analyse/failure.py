"""Automatic failure analysis of a toppling slope: failure surface, zones, S/H and T/H.

Pure numpy on arrays, so it is unit-tested with synthetic fields. Everything is in the
*slope frame*: x along the normal to the main joints, pointing out of the slope (towards the
face), y along the main joints, pointing up; columns (bands between main joints) are numbered
1, 2, ... from the toe into the slope. ``slope_frame`` maps scene coordinates into it.

Definitions (thesis §5.2.4.3, §5.3.3.2; its Fig 5-24 is not in the text, so S and T are our
reading of it):

* failure point of a column: the height (y) below which its discs stay put and above which
  they move as a broken-off part: displacement magnitudes fitted by zero below a cut and a
  straight line above it (a jump for a sliding part, a ramp from zero for a part rotating
  about a hinge at the cut; a threshold on the magnitudes would put a hinge too high by
  the threshold over the rotation), moved to the median of the cracks (broken bonds) within
  ``band`` of it when there are any;
* failure surface: a line fitted through the columns' failure points; two lines (split at
  the best break point, each through >= 3 points) when that lowers the squared residual
  more than it does for all but a share ``alpha`` of straight lines with scatter
  (``split_p_value``) and the two angles differ by >= ``min_angle_difference``;
  phi is the angle of a line to the normal of the main joints, positive rising into the
  slope; the overall surface is the one line through all the points, also where two are
  fitted (``overall_surface``), whose phi compares runs that split differently; over several
  runs of one model the same test with one cut common to them (``pooled_split_p_value``), as
  a bend a run's few points show weakly adds up over the runs;
* zones per column, from its top point: ``no-movement`` (total displacement below
  ``still``), ``stable`` (moved, but came to rest), ``toppling`` (still moving, the top moving
  more than twice as much as the base), ``sliding`` (still moving, base moving with the top);
  ``empty`` for a column without rock to judge (a toe column only a few discs high, which
  the packing can leave without bonded discs or whose loose discs drop off the table before
  the last equilibrium): it has no zone of its own and counts for neither distance;
* T: horizontal distance from the toe to the far edge of the last toppling or sliding column;
  S: the same to the far edge of the last column that moved at all (start of no-movement).
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Callable, Optional, Sequence

import numpy as np


def slope_frame(points: np.ndarray, toe: Sequence[float], joint_dip_deg: float) -> np.ndarray:
    """Scene xy-points into the slope frame, origin at the toe: y along the main joints, whose
    direction is ``joint_dip_deg`` (degrees counter-clockwise from +x, pointing up), x that
    direction turned 90 degrees clockwise (towards the face when the slope lies to the left
    of the face, as in all our scenes)."""
    a = math.radians(joint_dip_deg)
    along = np.array([math.cos(a), math.sin(a)])
    normal = np.array([along[1], -along[0]])
    d = np.asarray(points, dtype=float)[:, :2] - np.asarray(toe, dtype=float)[:2]
    return np.column_stack((d @ normal, d @ along))


def rotation_deg(before: np.ndarray, after: np.ndarray) -> float:
    """Best-fit rigid rotation (degrees, counter-clockwise) taking points ``before`` to ``after``."""
    p = before - before.mean(axis=0)
    q = after - after.mean(axis=0)
    return math.degrees(math.atan2(np.sum(p[:, 0] * q[:, 1] - p[:, 1] * q[:, 0]), np.sum(p * q)))


def _suffix_sums(values: np.ndarray) -> np.ndarray:
    """Sums of ``values[k:]`` for k = 0..n (the last is 0)."""
    return np.concatenate((np.cumsum(values[::-1])[::-1], [0.0]))


def hinge_cut(y: np.ndarray, d: np.ndarray) -> int:
    """Index k into ascending heights ``y`` that best splits displacement magnitudes ``d`` into
    zero below (d[:k]) and a straight line in y from k on: least squares over all k, each in
    O(1) from prefix and suffix sums."""
    n, s_y, s_yy = _suffix_sums(np.ones_like(y)), _suffix_sums(y), _suffix_sums(y * y)
    s_d, s_dy, s_dd = _suffix_sums(d), _suffix_sums(d * y), _suffix_sums(d * d)
    det = n * s_yy - s_y * s_y
    safe = np.where(det > 1e-12 * np.maximum(n * s_yy, 1e-300), det, np.inf)  # one height: a constant
    line = np.where(np.isfinite(safe), (s_yy * s_d * s_d - 2 * s_y * s_d * s_dy + n * s_dy * s_dy) / safe,
                    s_d * s_d / np.maximum(n, 1))  # explained by the best line (or constant)
    below = np.concatenate(([0.0], np.cumsum(d * d)))  # discs below the cut should not move
    return int(np.argmin(below + s_dd - line))


def failure_point(pos: np.ndarray, disp: np.ndarray, moved_threshold: float,
                  cracks: Optional[np.ndarray] = None, band: float = 0.0) -> Optional[tuple[float, float]]:
    """(x, y) where a column's discs (positions ``pos`` before, displacements ``disp``) change
    from unmoved below to moving as a part above (see the module's definitions); None if no
    disc moved more than ``moved_threshold``. ``cracks``: crack positions."""
    magnitude = np.linalg.norm(disp, axis=1)
    if not (magnitude > moved_threshold).any():
        return None
    order = np.argsort(pos[:, 1])
    y, d = pos[order, 1], magnitude[order]
    k = hinge_cut(y, d)
    cut = y[0] if k == 0 else (y[-1] if k == len(y) else 0.5 * (y[k - 1] + y[k]))
    if cracks is not None and len(cracks) and band > 0:
        x_lo, x_hi = pos[:, 0].min(), pos[:, 0].max()
        near = cracks[(cracks[:, 0] >= x_lo) & (cracks[:, 0] <= x_hi) & (np.abs(cracks[:, 1] - cut) <= band)]
        if len(near):
            cut = float(np.median(near[:, 1]))
    return float(pos[:, 0].mean()), float(cut)


SPLIT_TEST_DRAWS = 4000  # straight lines the two-planes test compares with: p resolved to 0.00025


@dataclass
class Plane:
    phi_deg: float  # angle to the normal of the main joints, positive rising into the slope
    slope: float  # dy/dx in the slope frame
    intercept: float  # y at x = 0 (the toe)
    x_range: tuple[float, float]


def _line(x: np.ndarray, y: np.ndarray) -> tuple[Plane, float]:
    slope, intercept = np.polyfit(x, y, 1)
    sse = float(np.sum((y - (slope * x + intercept)) ** 2))
    return Plane(math.degrees(math.atan(-slope)), float(slope), float(intercept), (float(x.min()), float(x.max()))), sse


def _best_split(p: np.ndarray) -> Optional[tuple[Plane, Plane, float]]:
    """Toe part and upper part of the points ``p`` (toe first), each a line through >= 3
    points, split where their summed squared residual is least; None below 6 points."""
    best = None
    for k in range(3, len(p) - 2):
        a, sse_a = _line(p[:k, 0], p[:k, 1])
        b, sse_b = _line(p[k:, 0], p[k:, 1])
        if best is None or sse_a + sse_b < best[2]:
            best = (a, b, sse_a + sse_b)
    return best


def _toe_first(points: Sequence[tuple[float, float]]) -> np.ndarray:
    return np.array(sorted(points, key=lambda q: -q[0]))  # the toe has the largest x


def _one_and_split(points: Sequence[tuple[float, float]]
                   ) -> tuple[Plane, float, Optional[tuple[Plane, Plane, float]], np.ndarray]:
    """The one line through the points with its squared residual, their best split
    (``_best_split``) and the points ordered toe first."""
    p = _toe_first(points)
    one, sse1 = _line(p[:, 0], p[:, 1])
    return one, sse1, _best_split(p), p


def _segment_sse(x: np.ndarray, y: np.ndarray) -> Callable[[int, int], np.ndarray]:
    """``sse(a, b)``: for each row of ``y`` (heights at ``x``), the squared residual of the line
    through points a .. b - 1, from running sums so that thousands of rows cost one pass.
    Centring and scaling ``x`` only conditions the sums: the residuals do not change."""
    x = (x - x.mean()) / x.std()
    sums = [np.concatenate([np.zeros((len(y), 1)), np.cumsum(v, axis=1)], axis=1)
            for v in (np.ones_like(y), np.broadcast_to(x, y.shape), np.broadcast_to(x * x, y.shape), y, y * y, x * y)]

    def sse(a: int, b: int) -> np.ndarray:
        m, sx, sxx, sy, syy, sxy = (s[:, b] - s[:, a] for s in sums)
        return syy - sy * sy / m - (sxy - sx * sy / m) ** 2 / (sxx - sx * sx / m)

    return sse


def split_p_value(points: Sequence[tuple[float, float]], draws: int = SPLIT_TEST_DRAWS) -> Optional[float]:
    """How strongly the failure points call for two planes: the share of straight lines with
    independent normal scatter, at the same x, whose best split (``_best_split``) lowers the
    squared residual at least as much as the points' does (Monte Carlo over ``draws`` lines,
    seeded, so a summary's value is reproducible; its resolution is 1 / (draws + 1)). The ratio
    does not depend on the line or the scatter's size, so the test is exact up to the draws.
    The F-test's (SSE2 / SSE1)^((n - 4) / 2) is exact only for six points (one split): where the
    break is searched for, its p < 0.05 calls one line two planes in 12 % of cases at 8 points
    and 22 % at 12. None below 6 points (no split into two lines of >= 3)."""
    if draws < 1:
        raise ValueError(f"draws = {draws}: the test needs at least 1 straight line to compare with")
    if len(points) < 6:
        return None
    _, sse1, best, p = _one_and_split(points)
    return _split_p(sse1, best[2], p[:, 0], draws)


def _split_p(sse1: float, sse2: float, x: np.ndarray, draws: int) -> float:
    """``split_p_value`` from the squared residuals of one line and of the best split."""
    if sse1 <= 0:
        return 1.0
    null = _null_split_ratios((tuple(x),), draws)
    return float((1 + np.count_nonzero(null <= sse2 / sse1)) / (draws + 1))


def _cuts(xs: Sequence[np.ndarray]) -> np.ndarray:
    """The cuts common to runs at ``xs``: midway between successive columns. A run has one
    failure point per column, at an x that varies by millimetres from run to run, so the runs'
    x closer than half their median spacing are one column: a cut never parts the runs' points
    of one column, and rounding the points to the millimetre does not move it."""
    pooled = np.unique(np.concatenate(xs))
    spacing = np.median(np.concatenate([np.diff(np.unique(x)) for x in xs]))
    k = np.flatnonzero(np.diff(pooled) > spacing / 2)
    return (pooled[k] + pooled[k + 1]) / 2


def _pooled_split_ratios(xs: Sequence[np.ndarray], ys: Sequence[np.ndarray]) -> np.ndarray:
    """For each row of the ``ys`` (one array of rows per run, heights at its ``xs``, toe first)
    and each of the ``_cuts``: the mean over the runs of each run's squared residual of two
    lines split at the cut over its residual of one line (1 for a run with fewer than 3 points
    on a side of the cut, or on a line). Each run's ratio depends neither on its line nor on
    its scatter, so runs that scatter more do not outweigh the others."""
    cuts = _cuts(xs)
    total = np.zeros((len(ys[0]), len(cuts)))
    for x, y in zip(xs, ys):
        sse, n = _segment_sse(x, y), len(x)
        whole = sse(0, n)
        for j, k in enumerate(np.count_nonzero(x[:, None] > cuts, axis=0)):
            if 3 <= k <= n - 3:
                total[:, j] += np.divide(sse(0, k) + sse(k, n), whole, out=np.ones_like(whole), where=whole > 0)
            else:
                total[:, j] += 1.0
    return total / len(xs)


def _pooled(runs: Sequence[Sequence[tuple[float, float]]]) -> Optional[tuple[list[np.ndarray], np.ndarray]]:
    """The runs of two points or more (toe first) and their ``_pooled_split_ratios`` by cut;
    None when no run has the 6 points a split needs."""
    runs = [_toe_first(points) for points in runs if len(points) >= 2]
    if not any(len(p) >= 6 for p in runs):
        return None
    return runs, _pooled_split_ratios([p[:, 0] for p in runs], [p[None, :, 1] for p in runs])[0]


def pooled_split_p_value(runs: Sequence[Sequence[tuple[float, float]]], draws: int = SPLIT_TEST_DRAWS
                         ) -> Optional[float]:
    """``split_p_value`` for several runs of one model (packing or layout draws) at once: whether
    their failure points call for two planes that break at the same place in each, each run
    with lines and scatter of its own. The statistic is the least over common cuts of the mean
    of the runs' ratios of two lines' squared residual to one line's; p is the share of
    ``draws`` sets of straight lines with independent normal scatter, at the runs' own x, whose
    statistic is as small (seeded). A break that each run's few points show only weakly adds
    up over the runs. Runs of fewer than 2 points are left out; None when no run has 6."""
    if draws < 1:
        raise ValueError(f"draws = {draws}: the test needs at least 1 set of straight lines to compare with")
    pooled = _pooled(runs)
    if pooled is None:
        return None
    runs, ratios = pooled
    null = _null_split_ratios(tuple(tuple(p[:, 0]) for p in runs), draws)
    return float((1 + np.count_nonzero(null <= ratios.min())) / (draws + 1))


def pooled_split(runs: Sequence[Sequence[tuple[float, float]]]
                 ) -> Optional[tuple[float, list[Optional[tuple[Plane, Plane]]]]]:
    """The common cut (an x) where ``pooled_split_p_value``'s statistic is least, and for each
    run in order its toe and upper lines at the cut (None for a run with fewer than 3 points
    on a side of it); None as that p is."""
    pooled = _pooled(runs)
    if pooled is None:
        return None
    kept, ratios = pooled
    cut = float(_cuts([p[:, 0] for p in kept])[np.argmin(ratios)])
    return cut, [_lines_at_cut(np.array(points, dtype=float).reshape(-1, 2), cut) for points in runs]


def _lines_at_cut(p: np.ndarray, cut: float) -> Optional[tuple[Plane, Plane]]:
    toe, upper = p[p[:, 0] > cut], p[p[:, 0] <= cut]
    return (_line(*toe.T)[0], _line(*upper.T)[0]) if min(len(toe), len(upper)) >= 3 else None


@functools.lru_cache(maxsize=16)
def _null_split_ratios(xs: tuple[tuple[float, ...], ...], draws: int) -> np.ndarray:
    """The least ``_pooled_split_ratios`` over the cuts of ``draws`` sets of straight lines with
    standard normal scatter at the runs' ``xs`` (seeded; for one run, its best split's ratio);
    cached, as a run's analysis and tests ask again for the same ``xs``."""
    rng = np.random.default_rng(0)
    return _pooled_split_ratios([np.array(x) for x in xs], [rng.standard_normal((draws, len(x))) for x in xs]).min(axis=1)


def fit_failure_surface(points: Sequence[tuple[float, float]], alpha: float = 0.05,
                        min_angle_difference: float = 5.0) -> list[Plane]:
    """One or two lines through the failure points, ordered from the toe into the slope: two
    when ``split_p_value`` < ``alpha`` and their angles differ by >= ``min_angle_difference``."""
    if len(points) < 2:
        raise ValueError(f"{len(points)} failure points: a failure surface needs at least 2")
    if not 0 < alpha < 1:
        raise ValueError(f"alpha = {alpha}: the two-planes test's level must lie between 0 and 1")
    one, sse1, best, p = _one_and_split(points)
    if (best and abs(best[0].phi_deg - best[1].phi_deg) >= min_angle_difference
            and _split_p(sse1, best[2], p[:, 0], SPLIT_TEST_DRAWS) < alpha):
        return [best[0], best[1]]
    return [one]


def overall_surface(points: Sequence[tuple[float, float]]) -> Plane:
    """The one line through all the failure points, also where ``fit_failure_surface`` finds
    two: its angle compares runs whose points split differently (a toe segment along the table
    and a steep upper one average out to the surface the slope fails along)."""
    if len(points) < 2:
        raise ValueError(f"{len(points)} failure points: a failure surface needs at least 2")
    return _one_and_split(points)[0]


def surface_angles(result: dict) -> dict:
    """A ``table_failure`` result's angles as summaries keep them: ``phi_deg``, one per
    surface, and ``phi_overall_deg`` (None without failure points)."""
    return {"phi_deg": [p.phi_deg for p in result["planes"]],
            "phi_overall_deg": result["overall"].phi_deg if result["overall"] else None}


def phi_text(angles: dict) -> str:
    """The surfaces' phi and, where there are two, the overall surface's beside them; "-"
    without a surface."""
    text = ", ".join(f"{p:.1f}" for p in angles["phi_deg"]) or "-"
    return f"{text} (overall {angles['phi_overall_deg']:.1f})" if len(angles["phi_deg"]) > 1 else text


def zone(top_displacement: float, still_moving: bool, base_displacement: float, still: float) -> str:
    """Zone of one column from its top point's displacement (see the module's definitions)."""
    if top_displacement < still:
        return "no-movement"
    if not still_moving:
        return "stable"
    return "toppling" if top_displacement > 2 * base_displacement else "sliding"


def column_failure(pos: np.ndarray, disp: np.ndarray, column: np.ndarray, tops: Sequence[Optional[int]],
                   moving: Sequence[bool], cracks: Optional[np.ndarray], band: float,
                   fell_off: Sequence[bool] = (), least_motion: float = 1e-5
                   ) -> tuple[list[str], list[tuple[float, float]]]:
    """Zones of columns 1..n and the failure points of those toppling or sliding.

    Every disc's position ``pos`` at the last equilibrium and displacement ``disp`` since, and
    its ``column`` (0: none, e.g. a disc that dropped off the table); per column k,
    ``tops[k - 1]`` the index of its top point's disc (None: nothing to judge, zone ``empty``)
    and ``moving[k - 1]`` whether that point still moves. ``band``: the reach of a failure point
    (cracks within it refine it, discs within it are the base that tells sliding from
    toppling). A top that moved less than 2 % of the farthest-moved top, or less than
    ``least_motion`` [m] (the model's resolution: elastic creep is not motion), has not moved. A
    top that fell off the table (``fell_off[k - 1]``) is judged too, but its fall does not set
    that scale: a metre's drop would make columns moved by centimetres unmoved."""
    if least_motion < 0:
        raise ValueError(f"least_motion = {least_motion} is invalid: it must be >= 0 m")
    if fell_off and len(fell_off) != len(tops):
        raise ValueError(f"fell_off has {len(fell_off)} entries for {len(tops)} columns: give one per column")
    top_disp = {k: float(np.linalg.norm(disp[i])) for k, i in enumerate(tops, start=1) if i is not None}
    in_slope = [d for k, d in top_disp.items() if not (fell_off and fell_off[k - 1])]
    still = max(0.02 * max(in_slope, default=0.0), least_motion)
    zones, points = [], []
    for k in range(1, len(tops) + 1):
        if k not in top_disp:
            zones.append("empty")
            continue
        members = column == k
        point = failure_point(pos[members], disp[members], still, cracks, band=band)
        base = 0.0
        if point:
            near_cut = members & (np.abs(pos[:, 1] - point[1]) < band)
            base = float(np.linalg.norm(disp[near_cut], axis=1).mean()) if near_cut.any() else 0.0
        zones.append(zone(top_disp[k], moving[k - 1], base, still=still))
        if point and zones[-1] in ("toppling", "sliding"):
            points.append(point)
    return zones, points


def table_failure(layout, reference: np.ndarray, now: np.ndarray, tops: dict[str, int],
                  moving: Callable[[str], bool], cracks: np.ndarray, tilt_deg: float, floor: float,
                  band: float, least_motion: float) -> dict:
    """Failure surface(s), zones, S/H and T/H of a tilting-table run (columns.ColumnLayout
    ``layout``) from its discs' positions at the last equilibrium (``reference``, table frame)
    and ``now``, the index of each column's top disc by label (``tops``), whether a column top
    still moves (``moving(label)``), the cracks' positions (table frame) and the failure tilt.
    A disc below height ``floor`` at the last equilibrium had dropped off the table: its fall is
    no column's motion. ``band`` and ``least_motion`` as in column_failure."""
    toe = (layout.toe_x, 0.0)
    on_table = reference[:, 1] > floor
    top_of = {label: i for label, i in tops.items() if on_table[i]}
    labels = [column_label(k) for k in range(1, layout.count + 1)]
    zones, points = column_failure(
        slope_frame(reference, toe, 90), now - reference, layout.columns_of(reference, floor),
        [top_of.get(label) for label in labels], [label in top_of and moving(label) for label in labels],
        slope_frame(np.asarray(cracks, dtype=float).reshape(-1, 2), toe, 90), band=band,
        fell_off=[label in top_of and now[top_of[label], 1] < floor for label in labels], least_motion=least_motion)
    planes = fit_failure_surface(points) if len(points) >= 2 else []
    height = layout.crest_height(tilt_deg)
    return {"planes": planes, "overall": overall_surface(points) if planes else None, "split_p": split_p_value(points),
            "failure_points": points, "zones": zones,
            "height": height, **zone_distances(zones, layout.far_edges(tilt_deg), height)}


def zone_distances(zones: Sequence[str], far_edges: Sequence[float], height: float) -> dict[str, Optional[float]]:
    """T/H and S/H from the zones of columns 1, 2, ... (toe first) and the horizontal distance
    from the toe to each column's far edge; None where the zone does not occur."""
    if height <= 0:
        raise ValueError(f"height = {height} is invalid: it must be > 0 m")
    failing = [d for z, d in zip(zones, far_edges) if z in ("toppling", "sliding")]
    moved = [d for z, d in zip(zones, far_edges) if z not in ("no-movement", "empty")]
    return {"t_over_h": max(failing) / height if failing else None,
            "s_over_h": max(moved) / height if moved else None}


def column_label(k: int) -> str:
    """Thesis label of column k (1-based, from the toe): A-1, B-2, ..., Z-26, AA-27, ..."""
    if k < 1:
        raise ValueError(f"column = {k} is invalid: it must be >= 1")
    letters, n = "", k
    while n:
        n, r = divmod(n - 1, 26)
        letters = chr(ord("A") + r) + letters
    return f"{letters}-{k}"
