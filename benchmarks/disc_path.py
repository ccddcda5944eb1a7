"""The same tilting-table runs on the disc path and on YADE's generic loop: figures and wall time.

Reads the summaries benchmarks/disc_path.table's lines wrote (run them first, e.g. with
``./toppling-sweep benchmarks/disc_path.table examples/tilting_table/run.py``) and prints, per
packing, both paths' failure tilt, φ, S/H, breaks, steps and wall time, whether every figure is
the same, the mean failure tilt of each path over the seeds, and the wall-time ratio:

    python3 benchmarks/disc_path.py
"""
import os
import statistics
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(REPO, "py"))

from toppling.io.reader import summary_of  # noqa: E402
from toppling.run.sweep import batch_table  # noqa: E402

FIGURES = ("failure_tilt_deg", "phi_overall_deg", "s_over_h", "tensile_breaks", "shear_breaks", "steps")


def pairs(table: str) -> dict:
    """{packing: {"fast": summary, "generic": summary}} of the table's finished lines."""
    runs = {}
    for line in batch_table.read(table).select(None):
        packing, path = line.description.rsplit("_", 1)
        summary = summary_of(os.path.join(REPO, line.parameters()["out"]))
        if summary:
            runs.setdefault(packing, {})[path] = summary
    return {k: v for k, v in runs.items() if len(v) == 2}


def main() -> None:
    runs = pairs(os.path.join(REPO, "benchmarks", "disc_path.table"))
    print("| packing | path | failure tilt (°) | φ overall (°) | S/H | breaks (t / s) | steps | wall (s) |")
    print("|---|---|---|---|---|---|---|---|")
    for packing, both in runs.items():
        for path in ("fast", "generic"):
            s = both[path]
            print(f"| {packing} | {path} | {s['failure_tilt_deg']} | {s['phi_overall_deg']:.4f} | {s['s_over_h']:.3f} | "
                  f"{s['tensile_breaks']} / {s['shear_breaks']} | {s['steps']} | {s['wall_time']:.0f} |")
    same = [p for p, b in runs.items() if all(b["fast"].get(k) == b["generic"].get(k) for k in FIGURES)]
    print(f"every figure the same on both paths: {len(same)} of {len(runs)} packings")
    seeds = [b for p, b in runs.items() if not p.startswith("r14")]
    for path in ("fast", "generic"):
        tilts = [b[path]["failure_tilt_deg"] for b in seeds if b[path]["failure_tilt_deg"] is not None]
        if len(tilts) > 1:
            print(f"{path}: mean failure tilt {statistics.mean(tilts):.2f} ± {statistics.stdev(tilts):.2f}° "
                  f"over {len(tilts)} seeds (R 2-8 mm)")
    ratios = [b["generic"]["wall_time"] / b["fast"]["wall_time"] for b in runs.values()]
    if ratios:
        print(f"wall time, generic over disc path: median x{statistics.median(ratios):.2f} "
              f"(x{min(ratios):.2f}-x{max(ratios):.2f})")


if __name__ == "__main__":
    main()
