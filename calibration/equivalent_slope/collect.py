"""Collect equivalent-slope summaries: one row per run, then per model (runs that differ only in
their packing seed) each figure as mean ± sd against the thesis' base model (§5.3.2), "met" when
the target (with its band) lies within mean ± 2 sd (issue 102's rule).

    source scripts/env.sh; /usr/bin/python3 calibration/equivalent_slope/collect.py [results/equivalent_slope [pattern ...]]
"""
import statistics
import sys
from typing import Optional, Sequence

from examples import params
from toppling.analyse.seeds import fmt
from toppling.io.reader import read_summaries

# rest_window only decides how soon a standing run is seen at rest; settled_dir where its settling was done
RUN_ONLY = ("out", "resume", "checkpoint_every", "max_wall_time", "post_failure_time", "seed", "exact_resume",
            "rest_window", "settled_dir")
# figure: (target, half-width of its band) — §5.3.2 and Fig 5-19
TARGETS = {"phi_overall_deg": (15.0, 3.0), "s_over_h": (0.79, 0.10), "t_over_h": (0.20, 0.10),
           "stable_first": (9, 1), "stable_last": (13, 1)}


def figures(s: dict) -> dict[str, Optional[float]]:
    """A run's figures as the targets name them (None where the run has none)."""
    stable = s.get("stable_zone_columns") or []
    return {"failed": float(bool(s.get("failed"))), "planes": s.get("planes", 0),
            "phi_overall_deg": s.get("phi_overall_deg"), "s_over_h": s.get("s_over_h"), "t_over_h": s.get("t_over_h"),
            "stable_first": min(stable) if stable else None, "stable_last": max(stable) if stable else None}


def model_of(s: dict) -> tuple:
    inputs = {"model": "ours", **s["inputs"]}  # runs from before JCFpm could run them
    return tuple(sorted((k, v) for k, v in inputs.items() if k not in RUN_ONLY))


def verdict(values: list[float], target: float, band: float) -> str:
    """Met when the target, with its band, lies within mean ± 2 sd (the two intervals meet); a
    single run has no sd: its value must lie in the band."""
    if not values:
        return "-"
    sd = statistics.stdev(values) if len(values) > 1 else 0.0
    return "met" if abs(statistics.mean(values) - target) <= 2 * sd + band else "not met"


def mean_sd(values: list[float], digits: int) -> str:
    if not values:
        return "-"
    if len(values) < 2:
        return fmt(values[0], digits)
    return f"{statistics.mean(values):.{digits}f} ± {statistics.stdev(values):.{digits}f}"


def model_text(model: tuple) -> str:
    keys = ("model", "strength_factor", "main_joint_friction", "base_plane_deg", "base_joints", "merged_pair", "spacing",
            "rmin", "rmax")
    inputs = dict(model)
    return ", ".join(f"{k} {inputs[k]}" for k in keys if k in inputs)


def main(folder: str, patterns: Sequence[str] = ("*",)) -> None:
    runs = read_summaries(folder, patterns)
    print("| run | seed | failed | planes | φ (°) | φ overall (°) | S/H | T/H | stable columns | tensile / shear breaks | steps | wall (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, s in runs.items():
        f = figures(s)
        stable = ", ".join(map(str, s.get("stable_zone_columns") or [])) or "-"
        print(f"| {name} | {s['inputs']['seed']} | {bool(s.get('failed'))} | {f['planes']} | {fmt(s.get('phi_deg', []))} | "
              f"{fmt(f['phi_overall_deg'])} | {fmt(f['s_over_h'], 2)} | {fmt(f['t_over_h'], 2)} | {stable} | "
              f"{s.get('tensile_breaks')} / {s.get('shear_breaks')} | {s.get('steps')} | {s.get('wall_time', 0):.0f} |")
    models: dict[tuple, list[dict]] = {}
    for s in runs.values():
        models.setdefault(model_of(s), []).append(figures(s))
    thesis = params.EQUIVALENT_SLOPE_RESULTS
    print(f"\nper model, mean ± sd over seeds; thesis φ {thesis['phi_deg']}, S/H {thesis['s_over_h']}, "
          f"T/H {thesis['t_over_h']}, stable zone {thesis['stable_zone_columns']}:\n")
    print("| model | seeds | failed | one plane | φ overall (°) | S/H | T/H | stable zone from | to |")
    print("|---|---|---|---|---|---|---|---|---|")
    for model, group in models.items():
        cells = []
        for key, digits in (("phi_overall_deg", 1), ("s_over_h", 2), ("t_over_h", 2), ("stable_first", 1), ("stable_last", 1)):
            values = [g[key] for g in group if g[key] is not None]
            cells.append(f"{mean_sd(values, digits)} ({verdict(values, *TARGETS[key])})")
        failed = sum(g["failed"] for g in group)
        one = sum(g["planes"] == 1 for g in group)
        print(f"| {model_text(model)} | {len(group)} | {failed:.0f} | {one} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "results/equivalent_slope", sys.argv[2:] or ("*",))
