"""The largest bond stresses of tilting-table runs stage by stage while (almost) no bond has
broken, and the tilts at which they reach a strength: the first cracks, read off the elastic stages.

    source scripts/env.sh; /usr/bin/python3 scripts/first_crack.py results/tilting_table/<run> [...] [--strength 85,100]

A run with bonds too strong to break (at Table 5-2's 209 kPa no bond breaks before 42 deg) gives
the whole curve: from it the first-crack tilt of any weaker strength, without a run per strength.
Per run prints R, packing seed, the largest tensile stress sigma_max [kPa] of the intact bonds
at the end of each stage with at most FEW_BROKEN broken bonds, the tilts at which the largest,
second and third largest reach each strength (linear between stages; "> t" if not by the last
such stage t), where those three bonds are at the last such stage (column, height), and the
run's failure tilt.
"""
import json
import os
import sys
from typing import Optional, Sequence

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bond_stress_history import bond_pairs, cell_arrays, read_grid, run_record, snapshots, stage_tilt, stage_tilts  # noqa: E402
from toppling.analysis import column_label  # noqa: E402
from toppling.columns import ColumnLayout  # noqa: E402


FEW_BROKEN = 10  # isolated bonds broken early (up to 10 in the 85 kPa runs' first stages) relieve no column
RANKS = 3  # the most stressed bonds followed: the first crack may stand alone, the next ones not


def elastic_peaks(folder: str) -> list[tuple[float, list[float], np.ndarray]]:
    """(tilt, the RANKS largest sigma_max [Pa] of the intact bonds, largest first, and their
    midpoints (x, y)) at the end of each stage up to the first with more than FEW_BROKEN broken bonds."""
    stages = stage_tilts(folder)
    peaks = []
    for time, path in snapshots(folder):
        if stages and time < stages[0][0]:  # the slope at the start tilt, still ringing from the ramp
            continue
        tilt = stage_tilt(time, stages)
        grid = read_grid(path)
        bonds = cell_arrays(grid)
        intact = np.flatnonzero(bonds["state"] == 1)
        if tilt is None or len(bonds["state"]) - len(intact) > FEW_BROKEN:
            break
        top = intact[np.argsort(bonds["sigma_max"][intact])[::-1][:RANKS]]
        discs = vtk_to_numpy(grid.GetPoints().GetData())[:, :2]
        peaks.append((tilt, list(bonds["sigma_max"][top]), discs[bond_pairs(grid)[top]].mean(axis=1)))
    return peaks


def crossing_tilt(peaks: Sequence[tuple], strength: float, rank: int = 1) -> Optional[float]:
    """The tilt at which the ``rank``-th largest stress reaches ``strength``, linear between
    stages; None if it does not by the last one. Reached at the first stage already gives that
    stage's tilt (an upper bound)."""
    curve = [(t, stresses[rank - 1]) for t, stresses, *_ in peaks]
    for (t0, s0), (t1, s1) in zip(curve[:1] + curve[:-1], curve):
        if s1 >= strength:
            return t1 if s1 == s0 else t0 + (t1 - t0) * (strength - s0) / (s1 - s0)
    return None


def layout_of(folder: str) -> Optional[ColumnLayout]:
    """The run's column layout, from its checkpoint (None without one)."""
    path = os.path.join(folder, "checkpoint.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return ColumnLayout(**json.load(f)["layout"])


def places(midpoints: np.ndarray, layout: ColumnLayout) -> str:
    """Where bonds are: column label and height above the table [cm]."""
    return ", ".join(f"{column_label(layout.column_of(x)) if layout.column_of(x) else '?'} {100 * y:.1f} cm"
                     for x, y in midpoints)


def row(folder: str, peaks: list[tuple], strengths: Sequence[float], tilts: Sequence[float]) -> str:
    record = run_record(folder)
    inputs = record.get("inputs", {})
    at = {t: stresses for t, stresses, _ in peaks}
    cells = [f"{at[t][0] / 1e3:.1f}" if t in at else "-" for t in tilts]
    last = f"> {peaks[-1][0]:g}" if peaks else "-"
    for s in strengths:
        reached = [crossing_tilt(peaks, s, rank) if peaks else None for rank in range(1, RANKS + 1)]
        cells.append(" / ".join(last if t is None else f"{t:.1f}" for t in reached))
    layout = layout_of(folder)
    cells.append(places(peaks[-1][2], layout) if peaks and layout else "-")
    failure = record.get("failure_tilt_deg")
    return (f"| {os.path.basename(folder.rstrip('/'))} | {1e3 * inputs.get('rmin', np.nan):g}–"
            f"{1e3 * inputs.get('rmax', np.nan):g} | {inputs.get('seed', 1)} | " + " | ".join(cells)
            + f" | {'-' if failure is None else f'{failure:g}'} |")


def main(folders: Sequence[str], strengths: Sequence[float]) -> None:
    peaks = {folder: elastic_peaks(folder) for folder in folders}
    tilts = sorted({t for curve in peaks.values() for t, *_ in curve})
    print("| run | R (mm) | seed | " + " | ".join(f"σ at {t:g}° (kPa)" for t in tilts)
          + "".join(f" | bonds 1 / 2 / 3 reach {s / 1e3:g} kPa at (°)" for s in strengths)
          + " | bonds 1 / 2 / 3 at the last such stage | failure tilt (°) |")
    print("|---|---|---|" + "---|" * (len(tilts) + len(strengths) + 2))
    for folder in folders:
        print(row(folder, peaks[folder], strengths, tilts))


if __name__ == "__main__":
    args = sys.argv[1:]
    given = [float(v) * 1e3 for v in args[args.index("--strength") + 1].split(",")] if "--strength" in args else [85e3]
    runs = [a for i, a in enumerate(args) if a != "--strength" and (i == 0 or args[i - 1] != "--strength")]
    if not runs:
        sys.exit(__doc__)
    main(runs, given)
