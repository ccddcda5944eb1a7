"""Why a tilting-table stage has not ended: the speed of each watched column at a checkpoint.

    ./yade -x -n -j1 scripts/stage_speeds.py results/tilting_table/<run>

A stage ends at rest once every watched column's median position is slower than ``rest_speed``
(1 mm/s) over a chunk (``toppling.tilting.stage_outcome``). Without local damping a tall column
can ring about its rest for the whole ``max_stage_time``; this prints, from the run's last
checkpoint, each watched column's median velocity (its discs' velocities, x and y apart: the
median position's while the column moves as one) and its fastest disc, so the column that
keeps the stage going is named.
"""
import json
import os
import sys

import numpy as np
from yade import O


def main(out: str) -> None:
    O.load(os.path.join(out, "checkpoint.yade.bz2"))
    with open(os.path.join(out, "checkpoint.json")) as f:
        state = json.load(f)
    phase = state["phase"]
    print(f"{out}: t = {O.time:.4f} s, phase {phase['name']} since t = {phase.get('start', O.time):.4f} s, "
          f"tilt {state['tilt']:g} deg")
    for label, group in zip(state["watched_columns"], state["watched"]):
        v = np.array([tuple(O.bodies[i].state.vel)[:2] for i in group])
        print(f"{label:>5} {len(group):3d} discs  median {1e3 * np.linalg.norm(np.median(v, axis=0)):.2e} mm/s  "
              f"fastest disc {1e3 * np.linalg.norm(v, axis=1).max():.2e} mm/s")


if __name__ == "__main__":
    main(sys.argv[1])
