"""One failure surface or two, over all the draws of one tilting-table model at once: each run
alone has about ten failure points, too few to show a break of 10 deg against centimetres of
scatter; the same break in every run adds up (toppling.analysis.pooled_split_p_value).

    source scripts/env.sh; /usr/bin/python3 scripts/pooled_surfaces.py results/tilting_table 'pattern' [...]

Takes the runs whose out folder matches a shell-style pattern and has failure points. Prints
each run's failure tilt, points, overall phi, split_p_value and its toe and upper phi at the
common cut (a run with fewer than three points on a side: '-'), then the pooled p, the common
cut (its distance from the toe), the mean ± standard deviation of those toe and upper phi and
in how many runs the toe line is the shallower (the thesis' random model: 14 deg at the toe,
24 above). The test is two-sided: bends either way add up.
"""
import os
import statistics
import sys

from toppling import analysis

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import collect_tilting_table as collect  # noqa: E402


def load(folder: str, patterns: list[str]) -> dict[str, dict]:
    """The summaries of collect_tilting_table.load that have failure points."""
    return {name: s for name, s in collect.load(folder, patterns).items() if s.get("failure_points")}


def spread(values: list[float]) -> str:
    return f"{statistics.mean(values):.1f} ± {statistics.stdev(values):.1f}" if len(values) > 1 else f"{values[0]:.1f}"


def main(folder: str, patterns: list[str]) -> None:
    runs = load(folder, patterns)
    if not runs:
        sys.exit(f"no summary.json with failure points under {folder} matches {patterns}")
    points = [s["failure_points"] for s in runs.values()]
    p, split = analysis.pooled_split_p_value(points), analysis.pooled_split(points)
    at_cut = split[1] if split else [None] * len(runs)
    print("| run | failure tilt (°) | failure points | overall φ (°) | split p | toe φ / upper φ at the common cut (°) |")
    print("|---|---|---|---|---|---|")
    for (name, s), lines in zip(runs.items(), at_cut):
        alone = analysis.split_p_value(s["failure_points"])
        print(f"| {name} | {s['failure_tilt_deg']} | {len(s['failure_points'])} | "
              f"{analysis.overall_surface(s['failure_points']).phi_deg:.1f} | {'-' if alone is None else f'{alone:.3f}'} | "
              f"{'-' if lines is None else f'{lines[0].phi_deg:.1f} / {lines[1].phi_deg:.1f}'} |")
    print(f"\n{len(runs)} runs pooled: p = {'-' if p is None else f'{p:.4f}'}", end="")
    pairs = [pair for pair in at_cut if pair]
    if pairs:
        print(f"; common cut {-split[0] * 1e3:.0f} mm from the toe; at it, over {len(pairs)} runs, toe φ "
              f"{spread([toe.phi_deg for toe, _ in pairs])}°, upper φ {spread([up.phi_deg for _, up in pairs])}°, "
              f"the toe shallower in {sum(toe.phi_deg < up.phi_deg for toe, up in pairs)}")
    else:
        print()


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
