"""The failure surface at the failure's onset, from a finished tilting-table run's ParaView series.

    ./yade -x -n scripts/onset_failure.py results/tilting_table/<run> [...]

The example analyses the displacements at the end of the post-failure run (0.3 s after the
failing stage), when a slope that failed high (38 deg) has already collapsed onto the table and
the toe columns' failure points lie on it. This runs the same analysis
(toppling.analysis.column_failure, the example's arguments) on the snapshot the example writes at
the end of the failing stage, when fail_columns column tops have just gone fail_displacement:
the discs' positions and velocities then, and the bonds broken by then (at their discs'
positions at the last equilibrium). Prints φ (and the overall surface's where the points split),
S/H, T/H and the toppling or sliding columns at the onset beside the summary's.
"""
import json
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bond_stress_history import bond_pairs, cell_arrays, read_grid, snapshots  # noqa: E402
from toppling import analysis  # noqa: E402
from toppling.analysis import phi_text  # noqa: E402
from toppling.columns import ColumnLayout  # noqa: E402


def disc_arrays(path: str) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    """Positions (x, y) and point data of a discs .vtu."""
    grid = read_grid(path)
    data = grid.GetPointData()
    fields = {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i)) for i in range(data.GetNumberOfArrays())}
    return vtk_to_numpy(grid.GetPoints().GetData())[:, :2], fields


def at_time(folder: str, kind: str, time: float) -> str:
    """The ``kind`` (discs, bonds) snapshot written at simulated ``time``."""
    written, path = min(snapshots(folder, kind), key=lambda entry: abs(entry[0] - time))
    if abs(written - time) > 1e-9 * max(1.0, time):
        raise ValueError(f"{folder}/paraview has no {kind} snapshot at t = {time} s: is the run finished?")
    return path


def onset(folder: str) -> dict:
    """φ, zones, S/H and T/H of the run in ``folder`` at the end of its failing stage."""
    with open(os.path.join(folder, "checkpoint.json")) as f:
        state = json.load(f)
    inputs, failed = state["inputs"], state["stages"][-1]
    if failed["outcome"] != "failed":
        raise ValueError(f"{folder} did not fail: nothing to analyse")
    layout = ColumnLayout(**state["layout"])
    reference = np.array(state["reference"])
    now, discs = disc_arrays(at_time(folder, "discs", failed["time"]))
    grid = read_grid(at_time(folder, "bonds", failed["time"]))
    broken = bond_pairs(grid)[cell_arrays(grid)["state"] > 1]
    index = {i: n for n, i in enumerate(state["ids"])}
    speed = np.linalg.norm(discs["velocity"][:, :2], axis=1)
    tops = {label: index[i] for label, i in zip(state["points"]["labels"], state["points"]["ids"])}
    result = analysis.table_failure(
        layout, reference, now, tops, lambda label: speed[tops[label]] > inputs["rest_speed"],
        0.5 * (reference[broken[:, 0]] + reference[broken[:, 1]]), failed["tilt"],
        floor=-2 * inputs["rmax"], band=2 * inputs["rmax"], least_motion=inputs["rmin"])  # as the example
    labels = [analysis.column_label(k) for k in range(1, layout.count + 1)]
    return {**analysis.surface_angles(result), "zones": dict(zip(labels, result["zones"])),
            "cracks": len(broken), "s_over_h": result["s_over_h"], "t_over_h": result["t_over_h"]}


def failing(zones: dict) -> str:
    return " ".join(label for label, z in zones.items() if z in ("toppling", "sliding")) or "-"


def main(folders: list[str]) -> None:
    print("| run | failure tilt (°) | φ at the onset (°) | S/H, T/H at the onset | failing columns at the onset "
          "| cracks at the onset | φ after the post-failure run (°) | S/H, T/H after it |")
    print("|---|---|---|---|---|---|---|---|")
    for folder in folders:
        with open(os.path.join(folder, "summary.json")) as f:
            summary = json.load(f)
        o = onset(folder)
        print(f"| {os.path.basename(folder.rstrip('/'))} | {summary['failure_tilt_deg']:g} "
              f"| {phi_text(o)} | {fmt(o['s_over_h'])}, {fmt(o['t_over_h'])} "
              f"| {failing(o['zones'])} | {o['cracks']} | {phi_text(summary)} "
              f"| {fmt(summary['s_over_h'])}, {fmt(summary['t_over_h'])} |")


def fmt(value) -> str:
    return "-" if value is None else f"{value:.2f}"


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
