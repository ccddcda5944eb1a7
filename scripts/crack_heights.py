"""Where a tilting-table run cracks first: cracks and peak bond stresses by height above the table.

    python3 scripts/crack_heights.py results/tilting_table/ideal_bond65_shrunk_joints001 [20]

For each snapshot of the bonds series (one at the start tilt, one per stage end) prints the
stage's tilt, the bonds broken since the previous snapshot, and how many of them, and of the
``top`` (20) most stressed intact bonds, are roots (bonds to a disc of the table's fixed layer,
centred within Rmax of the table as the example fixes them: where the columns are tied to the
table) or lie in each band of height above the table (y = 0); the ideal model's design plane
rises from the toe to 80 mm at the seventh column. A slope that topples along a surface through
the columns cracks above the roots; one that breaks off the table cracks at them.
"""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bond_stress_history import cell_arrays, read_grid, run_record, snapshot_label, snapshots, stage_tilts  # noqa: E402

BANDS_MM = (0.0, 20.0, 50.0, 100.0, np.inf)  # heights above the table of the bonds not at a root


def bonds_of_snapshot(path: str, rmax: float) -> tuple[np.ndarray, np.ndarray, dict[str, np.ndarray]]:
    """Midpoint heights y and root flags of the bonds of one bonds .vtu, and its cell arrays."""
    grid = read_grid(path)
    y = vtk_to_numpy(grid.GetPoints().GetData())[:, 1]
    ends = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 2)
    return 0.5 * (y[ends[:, 0]] + y[ends[:, 1]]), (y <= rmax)[ends].any(axis=1), cell_arrays(grid)


def band_counts(heights: np.ndarray, root: np.ndarray) -> list[int]:
    """Roots, then the others in each band of BANDS_MM (``heights`` in m)."""
    return [int(root.sum())] + np.histogram(1e3 * heights[~root], bins=BANDS_MM)[0].tolist()


def main(folder: str, top: int = 20) -> None:
    rmax = run_record(folder)["inputs"]["rmax"]
    stages = stage_tilts(folder)
    names = [f"{lo:g}–{hi:g}" if np.isfinite(hi) else f"≥ {lo:g}" for lo, hi in zip(BANDS_MM, BANDS_MM[1:])]
    print("Bonds by place: roots, then heights above the table (mm) " + ", ".join(names))
    print(f"| tilt (°) | new cracks | new cracks by height | {top} most stressed intact bonds by height |")
    print("|---|---|---|---|")
    broken_before = 0
    for time, path in snapshots(folder):
        tilt = snapshot_label(time, stages)
        height, root, bonds = bonds_of_snapshot(path, rmax)
        new = np.flatnonzero(bonds["state"] > 1)[broken_before:]  # the series lists breaks in their order
        intact = np.flatnonzero(bonds["state"] == 1)
        peaks = intact[np.argsort(bonds["sigma_max"][intact])[::-1][:top]]
        cracks, stressed = band_counts(height[new], root[new]), band_counts(height[peaks], root[peaks])
        print(f"| {tilt} | {len(new)} | {cracks} | {stressed} |")
        broken_before += len(new)


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) == 3 else 20)
