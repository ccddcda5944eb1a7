"""One failure surface or two, over all the draws of one tilting-table model at once: each run
alone has about ten failure points, too few to show a break of 10 deg against centimetres of
scatter; the same break in every run adds up (toppling.analyse.failure.pooled_split_p_value).

    source scripts/env.sh; /usr/bin/python3 calibration/tilting_table/pooled_surfaces.py results/tilting_table 'pattern' [...]
    source scripts/env.sh; /usr/bin/python3 calibration/tilting_table/pooled_surfaces.py --record [records/random_draws.csv]

Takes the runs whose out folder matches a shell-style pattern and has failure points, or, with
``--record``, the random model's draws in the record (records/random_draws.csv), so that the verdict over all draws can be recomputed on a machine that has
none of the runs. Prints each run's failure tilt, points, overall phi, split_p_value and its toe
and upper phi at the common cut (a run with fewer than three points on a side: '-'), then the
failure tilt over the runs against the thesis' (``failure_tilt_line``), the pooled p, the common
cut (its distance from the toe), the mean ± standard deviation of those toe and upper phi and in
how many runs the toe line is the shallower, and the verdict of the rule for the thesis' two
surfaces (``two_surfaces_verdict``), and where the thesis' one run falls among ours
(``thesis_among_draws``). The test is two-sided: bends either way add up.
"""
import csv
import os
import statistics
import sys
from typing import Iterable, Optional

from examples import params
from toppling.analyse import failure
from toppling.analyse.seeds import (difference_from, failed_seeds, first_stage_failure, inside_band, mean_against,
                                    stats_text, within)
from toppling.io.reader import read_summaries

RECORD = os.path.join(os.path.dirname(os.path.abspath(__file__)), "records", "random_draws.csv")
THESIS_PHI_DEG = tuple(params.TILTING_TABLE_RESULTS["random"]["phi_deg"])  # the toe and upper surfaces
THESIS_TILT_DEG = params.TILTING_TABLE_RESULTS["random"]["failure_tilt_deg"]
TOLERANCE_DEG = params.TARGET_TOLERANCE_DEG
UPPER_BOUND = "≤"  # printed before a tilt that is only an upper bound: the draw failed in its first stage
SPLIT_LEVEL = 0.05


def load(folder: str, patterns: list[str]) -> dict[str, dict]:
    """The summaries of the runs in ``folder`` matching ``patterns`` that have failure points."""
    return {name: s for name, s in read_summaries(folder, patterns).items() if s.get("failure_points")}


def read_record(lines: Iterable[str]) -> dict[str, dict]:
    """Runs by name ("line N: <draw>") as summaries (``failure_tilt_deg``,
    ``failed_in_first_stage`` for an upper bound, the thesis' tilt, and ``failure_points`` in
    the slope frame, m: x negative into the slope) from the record's CSV lines (line, draw,
    failure_tilt_deg, upper_bound, failure_points_mm: "mm from the toe:mm high" pairs)."""
    runs = {}
    for row in csv.DictReader(lines):
        runs[f"line {row['line']}: {row['draw']}"] = {
            "failure_tilt_deg": float(row["failure_tilt_deg"]),
            "failed_in_first_stage": bool(int(row["upper_bound"])),
            "thesis": {"failure_tilt_deg": THESIS_TILT_DEG},
            "failure_points": [[-float(x) * 1e-3, float(y) * 1e-3]
                               for x, y in (point.split(":") for point in row["failure_points_mm"].split())]}
    return runs


def tilt_text(s: dict) -> str:
    tilt = f"{s['failure_tilt_deg']:g}"  # a run with failure points failed at a tilt
    return f"{UPPER_BOUND} {tilt}" if first_stage_failure(s) else tilt


def failure_tilt_line(runs: dict[str, dict]) -> str:
    """The failure tilt over the runs as the collect script's seed sections give it: mean ±
    standard deviation and range of the runs that failed past their first stage, how many runs
    failed within the issue's tolerance of the thesis' tilt (an upper bound counts outside), and
    the mean against the thesis by two standard errors (mean_against)."""
    group = list(runs.values())
    targets = {s["thesis"]["failure_tilt_deg"] for s in group}
    if len(targets) > 1:
        return f"failure tilt: not pooled, the runs are of models with different thesis' tilts {sorted(targets)}"
    tilts, target = [s["failure_tilt_deg"] for s in failed_seeds(group)], targets.pop()
    inside = inside_band(tilts, target, TOLERANCE_DEG)
    bounds = [tilt_text(s) for s in group if first_stage_failure(s)]
    bounds = f", {', '.join(bounds)} left out" if bounds else ""
    if len(tilts) < 2:
        return f"failure tilt: {len(tilts)} of {len(group)} runs failed past their first stage{bounds}"
    return (f"failure tilt over {len(tilts)} runs: {stats_text(tilts)}° ({min(tilts):g}–{max(tilts):g}°), "
            f"{inside} of {len(group)} within {TOLERANCE_DEG:g}° of the thesis' {target:g}°{bounds}; "
            f"mean − thesis {mean_against(tilts, target, TOLERANCE_DEG)}")


def spread(values: list[float]) -> str:
    return f"{statistics.mean(values):.1f} ± {statistics.stdev(values):.1f}" if len(values) > 1 else f"{values[0]:.1f}"


def two_surfaces_verdict(p: Optional[float], pairs: list) -> str:
    """The rule set down before the random draws were rerun (docs/tilting_table.md, "Packings 5
    and 6 of the random model rerun"): "met" when the pooled p is below SPLIT_LEVEL and the mean
    toe and upper phi at the common cut are each within the issue's 3 deg of the thesis' by two
    standard errors; "not met" when p is not below it or a mean is outside by two standard
    errors; "undecided" otherwise (also with fewer than three runs split at the cut). Each mean's
    difference from the thesis, its standard error and its side's verdict follow in brackets."""
    if p is not None and p >= SPLIT_LEVEL:
        return f"not met (p ≥ {SPLIT_LEVEL:g})"
    if p is None or len(pairs) < 3:
        return "undecided (too few runs split at the common cut)"
    sides = []
    for side, (name, thesis) in enumerate(zip(("toe", "upper"), THESIS_PHI_DEG)):
        d, se = difference_from([pair[side].phi_deg for pair in pairs], thesis)
        sides.append((name, d, se, within(d, se, TOLERANCE_DEG)))
    verdicts = [side[3] for side in sides]
    verdict = "met" if verdicts == ["yes", "yes"] else "not met" if "no" in verdicts else "undecided"
    margins = "; ".join(f"{name} mean − thesis {d:+.1f} ± {se:.1f}° (SE): {v}" for name, d, se, v in sides)
    return f"{verdict} ({margins})"


def thesis_among_draws(pairs: list) -> str:
    """Where the thesis' one run falls among ours: how many of the runs split at the common cut
    have a toe line as shallow as the thesis' toe surface or shallower, an upper line as steep as
    its upper surface or steeper, and both. Beside the rule, not in its place: the rule asks
    whether our mean is the thesis' value; this, whether the thesis' value is one our draws give."""
    toe, upper = THESIS_PHI_DEG
    shallow = [pair[0].phi_deg <= toe for pair in pairs]
    steep = [pair[1].phi_deg >= upper for pair in pairs]
    return (f"the thesis' run among these {len(pairs)}: toe φ ≤ {toe:g}° in {sum(shallow)}, "
            f"upper φ ≥ {upper:g}° in {sum(steep)}, both in {sum(a and b for a, b in zip(shallow, steep))}")


def main(runs: dict[str, dict]) -> None:
    points = [s["failure_points"] for s in runs.values()]
    p, split = failure.pooled_split_p_value(points), failure.pooled_split(points)
    at_cut = split[1] if split else [None] * len(runs)
    print("| run | failure tilt (°) | failure points | overall φ (°) | split p | toe φ / upper φ at the common cut (°) |")
    print("|---|---|---|---|---|---|")
    for (name, s), lines in zip(runs.items(), at_cut):
        alone = failure.split_p_value(s["failure_points"])
        print(f"| {name} | {tilt_text(s)} | {len(s['failure_points'])} | "
              f"{failure.overall_surface(s['failure_points']).phi_deg:.1f} | {'-' if alone is None else f'{alone:.3f}'} | "
              f"{'-' if lines is None else f'{lines[0].phi_deg:.1f} / {lines[1].phi_deg:.1f}'} |")
    print(f"\n{failure_tilt_line(runs)}")
    print(f"{len(runs)} runs pooled: p = {'-' if p is None else f'{p:.4f}'}", end="")
    pairs = [pair for pair in at_cut if pair]
    if pairs:
        print(f"; common cut {-split[0] * 1e3:.0f} mm from the toe; at it, over {len(pairs)} runs, toe φ "
              f"{spread([toe.phi_deg for toe, _ in pairs])}°, upper φ {spread([up.phi_deg for _, up in pairs])}°, "
              f"the toe shallower in {sum(toe.phi_deg < up.phi_deg for toe, up in pairs)}")
        print(thesis_among_draws(pairs))
    else:
        print()
    print(f"the thesis' two surfaces ({THESIS_PHI_DEG[0]:g}° under {THESIS_PHI_DEG[1]:g}°) over these {len(runs)} runs: "
          f"{two_surfaces_verdict(p, pairs)}")


def runs_from(argv: list[str]) -> dict[str, dict]:
    """The runs the command line names (module docstring); exits with a message when there are none."""
    if argv[:1] == ["--record"]:
        path = argv[1] if len(argv) > 1 else RECORD
        with open(path, newline="") as f:
            runs = read_record(f)
        where = f"the record in {path}"
    else:
        runs, where = load(argv[0], argv[1:]), f"summary.json with failure points under {argv[0]} matching {argv[1:]}"
    if not runs:
        sys.exit(f"no runs: {where} has none")
    return runs


if __name__ == "__main__":
    if len(sys.argv) < 3 and sys.argv[1:2] != ["--record"]:
        sys.exit(__doc__)
    main(runs_from(sys.argv[1:]))
