"""How many neighbours a disc of a tilting-table run has within each bond gap: the bond density.

    python3 scripts/bond_coordination.py results/tilting_table/ideal_bond62_shrunk_joints001 [0.5,1.05,2.1]

Reads the discs as the run bonded them (the first snapshot of its ParaView series) and prints,
for each gap [mm], the mean number of discs within that gap of a disc's surface, which is the
mean number of bonds per disc before the joints cut the bonds across them. A gap fixed in mm
(Table 5-2: 1.05 mm) bonds the more neighbours the finer the packing.
"""
import os
import sys
from collections import defaultdict
from typing import Sequence

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bond_stress_history import read_grid  # noqa: E402


def surface_gaps(centres: np.ndarray, radii: np.ndarray, reach: float) -> np.ndarray:
    """Surface-to-surface distances of all pairs of discs closer than ``reach`` (grid search)."""
    cell = 2 * radii.max() + reach
    cells = defaultdict(list)
    for i, key in enumerate(map(tuple, np.floor(centres / cell).astype(int))):
        cells[key].append(i)
    gaps = []
    for (cx, cy), members in cells.items():
        near = np.array([j for dx in (-1, 0, 1) for dy in (-1, 0, 1) for j in cells.get((cx + dx, cy + dy), ())])
        for i in members:
            others = near[near > i]
            d = np.linalg.norm(centres[others] - centres[i], axis=1) - radii[others] - radii[i]
            gaps.extend(d[d <= reach])
    return np.array(gaps)


def coordination(centres: np.ndarray, radii: np.ndarray, gaps: Sequence[float]) -> list[float]:
    """Mean number of neighbours within each of ``gaps`` [m] of a disc's surface."""
    pairs = surface_gaps(centres, radii, max(gaps))
    return [2 * float((pairs <= g).sum()) / len(radii) for g in gaps]


def main(folder: str, gaps_mm: Sequence[float] = (0.525, 1.05, 2.1)) -> None:
    discs = read_grid(os.path.join(folder, "paraview", "discs_00000.vtu"))
    centres = vtk_to_numpy(discs.GetPoints().GetData())[:, :2]
    radii = vtk_to_numpy(discs.GetPointData().GetArray("radius"))
    print(f"{len(radii)} discs, mean radius {1e3 * radii.mean():.2f} mm")
    print("| gap (mm) | " + " | ".join(f"{g:g}" for g in gaps_mm) + " |")
    print("|---|" + "---|" * len(gaps_mm))
    values = coordination(centres, radii, [1e-3 * g for g in gaps_mm])
    print("| neighbours per disc | " + " | ".join(f"{v:.2f}" for v in values) + " |")


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    main(sys.argv[1], [float(g) for g in sys.argv[2].split(",")] if len(sys.argv) == 3 else (0.525, 1.05, 2.1))
