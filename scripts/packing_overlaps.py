"""The overlaps a tilting-table run's discs had when they were bonded.

    ./yade -x -n scripts/packing_overlaps.py results/tilting_table/<run> [...]

Reads each run's checkpoint: the discs' radii from the scene, their positions as bonded from
the ParaView series' ``reference`` in checkpoint.json (the run's own ``reference`` moves to each
equilibrium). Prints the number of overlapping pairs, their mean, 99th
percentile and largest overlap (with the pair's ids), and the discs' total area: what
``shrink_overlaps`` removes and what it costs.
"""
import json
import math
import sys

import numpy as np
from yade import O

from toppling import packing


def bonded_discs(out: str) -> tuple[list[int], list[tuple[float, float]], list[float]]:
    """Ids, centres as bonded and radii of a run's discs."""
    O.load(f"{out}/checkpoint.yade.bz2")
    with open(f"{out}/checkpoint.json") as f:
        state = json.load(f)
    series = state["series"]  # started right after bonding, before the first step
    centres = [(x, y) for x, y, *_ in series["reference"]]
    return series["ids"], centres, [O.bodies[i].shape.radius for i in series["ids"]]


def report(out: str) -> str:
    ids, centres, radii = bonded_discs(out)
    overlaps = sorted(((radii[i] + radii[j] - distance, ids[i], ids[j])
                       for i, j, distance in packing.pairs_within(centres, radii, 0.0)), reverse=True)
    area = math.pi * sum(r * r for r in radii)
    positive = np.array([u for u, _, _ in overlaps if u > 0])
    if not positive.size:
        return f"{out}: {len(ids)} discs, no overlapping pair; disc area {area:.6f} m2"
    largest, a, b = overlaps[0]
    return (f"{out}: {len(ids)} discs, {positive.size} overlapping pairs; overlap mean {positive.mean():.2g} m, "
            f"99th percentile {np.percentile(positive, 99):.2g} m, largest {largest:.2g} m (discs {a} and {b}); "
            f"disc area {area:.6f} m2")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for folder in sys.argv[1:]:
        print(report(folder), flush=True)
