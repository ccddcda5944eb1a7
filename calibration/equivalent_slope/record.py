"""The families' record (records/family_runs.csv, ``toppling.io.records``): one row per finished
run, the figures families_report.py reads.

    source scripts/env.sh; /usr/bin/python3 calibration/equivalent_slope/record.py [results/equivalent_slope/families]
    source scripts/env.sh; /usr/bin/python3 calibration/equivalent_slope/record.py --missing examples/equivalent_slope/families.table

The first adds (or replaces) the rows of the folder's finished runs; the second prints the
table's lines the record lacks, for ``toppling-sweep --lines``.
"""
import os
import sys
from typing import Any

from collect import figures  # this folder's: runs as a script
from toppling.io import records

RECORD = os.path.join(os.path.dirname(__file__), "records", "family_runs.csv")
RUN = ("tensile_breaks", "shear_breaks", "steps", "wall_time")
NUMBERS = ("seed", "main_joint_friction", "failed", "planes", "phi_overall_deg", "s_over_h", "t_over_h",
           "stable_first", "stable_last", *RUN)


def row(name: str, s: dict[str, Any]) -> dict[str, Any]:
    """A finished run's row: its seed and friction, its figures (collect.figures), its cost and code."""
    return {"run": name, "seed": s["inputs"]["seed"], "main_joint_friction": s["inputs"]["main_joint_friction"],
            **figures(s), **{k: s.get(k) for k in RUN}, "commit": records.commit(s)}


def read() -> dict[str, dict[str, Any]]:
    return records.read(RECORD, NUMBERS)


def update(folder: str) -> dict[str, dict[str, Any]]:
    return records.update(RECORD, folder, row, NUMBERS)


if __name__ == "__main__":
    if sys.argv[1:2] == ["--missing"]:
        print(records.missing(sys.argv[2], read()))
    else:
        folder = sys.argv[1] if len(sys.argv) > 1 else "results/equivalent_slope/families"
        print(f"{len(update(folder))} runs in {os.path.relpath(RECORD)}")
