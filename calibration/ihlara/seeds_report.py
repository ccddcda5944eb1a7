"""The Ihlara cliff over five packings (examples/field/ihlara_seeds.table; on finer discs,
calibration/ihlara/finer.table): each finished run of the folders added to the record
(records/seed_runs.csv, ``toppling.io.records``), then per study (a run's name without its seed)
how many packings fail and which columns topple, beside the thesis (docs/cases/ihlara.md).

    source scripts/env.sh; /usr/bin/python3 calibration/ihlara/seeds_report.py [results/ihlara_seeds] [results/ihlara_finer]
"""
import os
import statistics
import sys
from typing import Any

from toppling.io import records

RECORD = os.path.join(os.path.dirname(__file__), "records", "seed_runs.csv")
NUMBERS = ("seed", "weathered_strength_factor", "rmax", "failed", "toppling_columns", "tensile_breaks", "shear_breaks",
           "simulated_time", "steps", "wall_time")
THESIS = {"intact": "stands until the tuff weathers (§5.4.1.2)",
          "weathered": "column 1 topples; column 2 moves but stands (Fig 5-38)",
          "eroded": "columns 1-3 topple (Fig 5-40)",
          "back_analysis": "column 1 tilts back, then the columns behind fail (Fig 5-42)"}


def row(name: str, s: dict[str, Any]) -> dict[str, Any]:
    zones = s.get("zones") or {}
    toppling = [label for label, zone in zones.items() if zone == "toppling"]
    stable = [label for label, zone in zones.items() if zone == "stable"]  # moved, came to rest
    return {"run": name, "seed": s["inputs"]["seed"], "case": s["inputs"]["case"],
            "weathered_strength_factor": s["inputs"]["weathered_strength_factor"], "rmax": s["inputs"]["rmax"],
            "failed": int(bool(s["failed"])),
            "toppling": " ".join(toppling), "toppling_columns": len(toppling), "moved_and_stood": " ".join(stable),
            **{k: s.get(k) for k in ("tensile_breaks", "shear_breaks", "simulated_time", "steps", "wall_time")},
            "commit": records.commit(s)}


def report(rows: dict[str, dict[str, Any]]) -> None:
    """Per study (a run's name without its seed: the case, or a prefix and the case) and thesis case."""
    print("| runs | Rmax (m) | packings that fail | columns toppling (moved and stood), by seed | breaks (tensile / "
          "shear), mean | wall (s), mean | thesis |\n|---|---|---|---|---|---|---|")
    studies = {name.rsplit("_s", 1)[0] for name in rows}
    for case, thesis in THESIS.items():
        for study in sorted(s for s in studies if s == case or s.endswith("_" + case)):
            runs = sorted((r for name, r in rows.items() if name.rsplit("_s", 1)[0] == study), key=lambda r: r["seed"])
            toppling = ", ".join(f"{int(r['seed'])}: {r['toppling'] or '-'}"
                                 + (f" ({r['moved_and_stood']})" if r["moved_and_stood"] else "") for r in runs)
            mean = lambda key: statistics.mean(r[key] for r in runs)  # noqa: E731
            print(f"| {study} | {runs[0]['rmax']:g} | {sum(r['failed'] for r in runs):.0f} of {len(runs)} | {toppling} | "
                  f"{mean('tensile_breaks'):.0f} / {mean('shear_breaks'):.0f} | {mean('wall_time'):.0f} | {thesis} |")


if __name__ == "__main__":
    for folder in sys.argv[1:] or ["results/ihlara_seeds"]:
        rows = records.update(RECORD, folder, row, NUMBERS)
    report(rows)
