"""The bonds broken, and of them the cracks in the rock, by the end of each stage of finished
tilting-table runs: two runs of one packing along different loading paths (a ramp to 26 deg,
or stages from 18 deg) compared tilt by tilt.

    ./yade -x -n scripts/stage_breaks.py results/tilting_table/<run> [...]

Reads each run's checkpoint (the scene keeps every break's time and discs, checkpoint.json each
stage's end time). A crack is a break of two discs each still held by at least two bonds at the
end of its stage (toppling.bonding.rock_breaks); the others freed a disc.
"""
import os
import sys

import numpy as np
from yade import O

from toppling import bonding, monitor, scene


def by_stage(stages: list[dict]) -> list[tuple[float, str, int, int]]:
    """For each of ``stages`` of the scene loaded: its tilt, its outcome, and the breaks and
    cracks recorded by its end (the breaks before the first stage count with it; each stage's
    are sorted at its end)."""
    times = scene.bond_law().breakTime
    rows, first, cracks = [], 0, 0
    for stage in stages:
        end = int(np.searchsorted(times, stage["time"], side="right"))
        cracks += len(bonding.rock_breaks(first, end - first))
        rows.append((stage["tilt"], stage["outcome"], end, cracks))
        first = end
    return rows


def main(folders: list[str]) -> None:
    print("| run | tilt (deg) | outcome | breaks | cracks |")
    print("|---|---|---|---|---|")
    for folder in folders:
        checkpoint = monitor.Checkpoint(folder)
        O.load(checkpoint.scene_path)
        name = os.path.basename(folder.rstrip("/"))
        for tilt, outcome, breaks, cracks in by_stage(checkpoint.load()["stages"]):
            print(f"| {name} | {tilt:.1f} | {outcome} | {breaks} | {cracks} |", flush=True)


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
