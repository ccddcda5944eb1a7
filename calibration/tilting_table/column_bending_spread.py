"""Bending strength of one continuous column by packing size, over packing seeds.

Runs calibration/tilting_table/column_bending.py (one ./yade process per column) for every size and seed given,
and prints per size the tilt at which each column broke and their mean and standard deviation:
whether the rock's strength in bending depends on the particle size, apart from the scatter of
the packing.

    python3 calibration/tilting_table/column_bending_spread.py bond_tensile_strength seeds rmin-rmax [rmin-rmax ...] [name=value ...]
    python3 calibration/tilting_table/column_bending_spread.py 55e3 1-10 0.001-0.004 0.001-0.0025

``seeds``: ``first-last``; ``name=value``: passed on to column_bending.py (``height=0.2``, ``bond_gap=0.735e-3``).
"""
import os
import re
import statistics
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FAILED = re.compile(r"^failed \(top moved [\d.]+ mm\) at ([\d.]+) deg", re.MULTILINE)


def failure_tilt(output: str) -> float:
    """The tilt [deg] at which column_bending.py's column broke, from what it printed."""
    match = FAILED.search(output)
    if not match:
        raise RuntimeError(f"column_bending.py printed no failure:\n{output[-2000:]}")
    return float(match.group(1))


def column(rmin: str, rmax: str, strength: str, seed: int, options: list[str]) -> float:
    command = [os.path.join(REPO, "yade"), "-x", "-n", "-j1", os.path.join(REPO, "calibration", "tilting_table", "column_bending.py"),
               rmin, rmax, strength, f"seed={seed}", *options]
    return failure_tilt(subprocess.run(command, capture_output=True, text=True, check=True, cwd=REPO).stdout)


def row(size: str, tilts: list[float]) -> str:
    spread = f"{statistics.mean(tilts):.1f} ± {statistics.stdev(tilts):.1f}" if len(tilts) > 1 else "-"
    return f"| {size} | {', '.join(f'{t:.1f}' for t in tilts)} | {spread} |"


def main(args: list[str]) -> None:
    positional = [a for a in args if "=" not in a]
    if len(positional) < 3 or not re.fullmatch(r"\d+-\d+", positional[1]):
        raise SystemExit(__doc__)
    strength, (first, last), sizes = positional[0], map(int, positional[1].split("-")), positional[2:]
    options = [a for a in args if "=" in a]
    print(f"| R (mm) | failure tilt per seed {first}-{last} (°) | mean ± sd (°) |\n|---|---|---|")
    for size in sizes:
        rmin, rmax = size.split("-")
        tilts = [column(rmin, rmax, strength, seed, options) for seed in range(first, last + 1)]
        print(row(f"{1e3 * float(rmin):g}–{1e3 * float(rmax):g}", tilts), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
