"""What moves in a Galandrood run: from its checkpoint, every disc's displacement since it was made
(State.refPos) and its speed, by distance behind the toe (table frame: the columns stand upright,
the toe at the largest x) and for the rock below the table plane; and the joints' slip and the
bonds' largest stresses against their strengths.

    ./yade -x -n -j1 calibration/galandrood/what_moves.py [results/galandrood/base]
"""
import sys

import numpy as np
from yade import O
from yade.wrapper import ParallelBondPhys, SmoothJointPhys

out = sys.argv[1] if len(sys.argv) > 1 else "results/galandrood/base"
O.load(f"{out}/checkpoint.yade.bz2")
states = [b.state for b in O.bodies if b is not None]
pos = np.array([[s.pos[0], s.pos[1]] for s in states])
ref = np.array([[s.refPos[0], s.refPos[1]] for s in states])
vel = np.array([[s.vel[0], s.vel[1]] for s in states])
moved, speed = np.linalg.norm(pos - ref, axis=1), np.linalg.norm(vel, axis=1)
print(f"t = {O.time:.3f} s, {len(states)} discs; displacement median {np.median(moved):.3f} m, max {moved.max():.3f} m; "
      f"speed median {np.median(speed):.3f} m/s, max {speed.max():.3f} m/s")
toe = ref[:, 0].max()
for lo, hi in ((0, 3), (3, 6), (6, 12), (12, 24)):
    sel = (toe - ref[:, 0] >= lo) & (toe - ref[:, 0] < hi) & (ref[:, 1] >= 0)
    print(f"columns {lo}-{hi} m behind the toe: {sel.sum()} discs, displacement median {np.median(moved[sel]):.3f} m, "
          f"speed median {np.median(speed[sel]):.3f} m/s, mean velocity ({vel[sel, 0].mean():.3f}, {vel[sel, 1].mean():.3f}) m/s")
below = ref[:, 1] < 0
print(f"rock below the table plane: {below.sum()} discs, displacement median {np.median(moved[below]):.4f} m, "
      f"max {moved[below].max():.3f} m")
joints = [i.phys for i in O.interactions if isinstance(i.phys, SmoothJointPhys)]
slips = np.array([p.slip for p in joints])
print(f"{len(joints)} joint contacts: {np.mean([p.isSlipping for p in joints]):.0%} slipping now, slip median "
      f"{1e3 * np.median(slips):.2f} mm, max {1e3 * slips.max():.1f} mm")
bonds = [i.phys for i in O.interactions if isinstance(i.phys, ParallelBondPhys) and i.phys.bondState == 1]
print(f"{len(bonds)} intact bonds: largest tensile stress {max(p.bondSigmaMax for p in bonds) / 1e6:.2f} MPa "
      f"(strength {bonds[0].bondTensileStrength / 1e6:.1f}), largest shear stress "
      f"{max(p.bondTauMax for p in bonds) / 1e6:.2f} MPa (cohesion {bonds[0].bondCohesion / 1e6:.1f})")
