"""One failure surface or two, over all the draws of one tilting-table model at once: each run
alone has about ten failure points, too few to show a break of 10 deg against centimetres of
scatter; the same break in every run adds up (toppling.analysis.pooled_split_p_value).

    source scripts/env.sh; /usr/bin/python3 scripts/pooled_surfaces.py results/tilting_table 'pattern' [...]

Takes the runs whose out folder matches a shell-style pattern and has failure points. Prints
each run's failure tilt, points, overall phi and split_p_value, then the pooled p, the common
cut (its distance from the toe), the mean ± standard deviation of the runs' toe and upper phi
at that cut (the runs with three points or more on each side) and in how many of them the toe
line is the shallower (the thesis' random model: 14 deg at the toe, 24 above). The test is
two-sided: bends either way add up.
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
    print("| run | failure tilt (°) | failure points | overall φ (°) | split p |")
    print("|---|---|---|---|---|")
    for name, s in runs.items():
        p = analysis.split_p_value(s["failure_points"])
        print(f"| {name} | {s['failure_tilt_deg']} | {len(s['failure_points'])} | "
              f"{analysis.overall_surface(s['failure_points']).phi_deg:.1f} | {'-' if p is None else f'{p:.3f}'} |")
    points = [s["failure_points"] for s in runs.values()]
    p = analysis.pooled_split_p_value(points)
    split = analysis.pooled_split(points)
    print(f"\n{len(runs)} runs pooled: p = {'-' if p is None else f'{p:.4f}'}", end="")
    if split and split[1]:
        cut, lines = split
        print(f"; common cut {-cut * 1e3:.0f} mm from the toe; at it, over {len(lines)} runs, toe φ "
              f"{spread([toe.phi_deg for toe, _ in lines])}°, upper φ {spread([up.phi_deg for _, up in lines])}°, "
              f"the toe shallower in {sum(toe.phi_deg < up.phi_deg for toe, up in lines)}")
    else:
        print()


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
