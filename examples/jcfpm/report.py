"""Our model beside JCFpm on the same scenes: the tables of docs/jcfpm.md from the runs of
examples/jcfpm/*.table (run them first, as each table's header says).

    source scripts/env.sh; /usr/bin/python3 examples/jcfpm/report.py [results/jcfpm]
"""
import statistics
import sys

from toppling.analyse.seeds import fmt
from toppling.io.reader import read_summaries


FAMILIES = "results/equivalent_slope/families"


def by_model(runs: dict) -> dict[str, list[dict]]:
    found: dict[str, list[dict]] = {}
    for s in runs.values():
        found.setdefault(s["inputs"]["model"], []).append(s)
    return found


def tilt_slide(folder: str) -> None:
    print("| atan μ (°) | ours slides at (°) | JCFpm slides at (°) |\n|---|---|---|")
    runs = by_model(read_summaries(f"{folder}/tilt_slide"))
    for ours, theirs in zip(*(sorted(runs[m], key=lambda s: s["reference"]) for m in ("ours", "jcfpm"))):
        print(f"| {ours['reference']:.2f} | {ours['slide_tilt_deg']:.2f} | {theirs['slide_tilt_deg']:.2f} |")


def block_on_incline(folder: str) -> None:
    print("\n| model | mode (thesis: topple) | toe moved (mm) | rotation (°) |\n|---|---|---|---|")
    for model, runs in by_model(read_summaries(f"{folder}/block_on_incline")).items():
        for s in runs:
            print(f"| {model} | {s['mode']} | {1e3 * s['translation']:.1f} | {s['rotation_deg']:.1f} |")


def column(folder: str) -> None:
    runs = by_model(read_summaries(f"{folder}/column"))
    beam = next(iter(runs.values()))[0]["beam_theory_deg"]
    print(f"\n| model | breaks at (°), beam theory {beam:.1f}° | steps | wall time (s) |\n|---|---|---|---|")
    for model, found in runs.items():
        tilts = [s["failure_tilt_deg"] for s in found]
        spread = f" ± {statistics.stdev(tilts):.1f} ({len(tilts)} seeds)" if len(tilts) > 1 else ""
        print(f"| {model} | {statistics.mean(tilts):.1f}{spread} | {statistics.mean(s['steps'] for s in found):.0f} | "
              f"{statistics.mean(s['wall_time'] for s in found):.0f} |")


def slopes(folder: str) -> None:
    """The tilting table and the equivalent slope, seed by seed (paired), where they have been run;
    the equivalent slope's ours are the families' base runs (the same settled rock)."""
    ours_slope = read_summaries(FAMILIES, [f"base_s{seed}" for seed in (1, 2, 3)])
    for case, also in (("tilting_table", {}), ("equivalent_slope", ours_slope)):
        runs = {**read_summaries(f"{folder}/{case}"), **also}
        if not runs:
            continue
        print(f"\n{case}:\n\n| seed | model | fails at (°) | φ (°) | S/H | T/H | stable columns | breaks | wall time (s) |\n"
              "|---|---|---|---|---|---|---|---|---|")
        for s in sorted(runs.values(), key=lambda s: (s["inputs"]["seed"], s["inputs"]["model"])):
            stable = ", ".join(map(str, s.get("stable_zone_columns") or [])) or "-"
            print(f"| {s['inputs']['seed']} | {s['inputs']['model']} | {fmt(s.get('failure_tilt_deg'))} | "
                  f"{fmt(s.get('phi_overall_deg'))} | {fmt(s.get('s_over_h'), 2)} | {fmt(s.get('t_over_h'), 2)} | "
                  f"{stable} | {s.get('tensile_breaks')} / {s.get('shear_breaks')} | {s.get('wall_time', 0):.0f} |")


if __name__ == "__main__":
    root = sys.argv[1] if len(sys.argv) > 1 else "results/jcfpm"
    tilt_slide(root)
    block_on_incline(root)
    column(root)
    slopes(root)
