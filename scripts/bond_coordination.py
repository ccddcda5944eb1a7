"""How many neighbours a disc of a tilting-table run has within each bond gap: the bond density.

    ./yade -x -n scripts/bond_coordination.py results/tilting_table/<run> [0.525,1.05,2.1]

Reads the discs as the run bonded them (``packing_overlaps.bonded_discs``: radii from the
checkpoint's scene, centres from its ParaView series' reference) and prints, for each gap [mm],
the mean number of discs within that gap of a disc's surface: the bonds per disc before the
joints cut those across them. A gap fixed in mm (Table 5-2: 1.05 mm) bonds the more neighbours
the finer the packing.
"""
import os
import sys
from typing import Sequence

import numpy as np

sys.path.insert(0, os.path.join(os.environ["TOPPLING_REPO"], "scripts"))  # set by the ./yade launcher
from packing_overlaps import bonded_discs  # noqa: E402
from toppling import packing  # noqa: E402


def coordination(centres: Sequence[tuple[float, float]], radii: Sequence[float], gaps: Sequence[float]) -> list[float]:
    """Mean number of neighbours within each of ``gaps`` [m] of a disc's surface."""
    pairs = packing.pairs_within(centres, radii, max(gaps))
    surface = np.array([distance - radii[i] - radii[j] for i, j, distance in pairs])
    return [2 * float((surface <= g).sum()) / len(radii) for g in gaps]


def main(folder: str, gaps_mm: Sequence[float] = (0.525, 1.05, 2.1)) -> None:
    _, centres, radii = bonded_discs(folder)
    print(f"{len(radii)} discs, mean radius {1e3 * np.mean(radii):.2f} mm")
    print("| gap (mm) | " + " | ".join(f"{g:g}" for g in gaps_mm) + " |")
    print("|---|" + "---|" * len(gaps_mm))
    values = coordination(centres, radii, [1e-3 * g for g in gaps_mm])
    print("| neighbours per disc | " + " | ".join(f"{v:.2f}" for v in values) + " |")


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    main(sys.argv[1], [float(g) for g in sys.argv[2].split(",")] if len(sys.argv) == 3 else (0.525, 1.05, 2.1))
