"""A block in Sagaseta's band (tan φ ≤ b/h < tan α: it should slide upright) and the joint contacts
that carry it: a 9 × 20 cm block, α 30°, φ 20°, settled on the level table, then tilted. Prints
every 0.01 s, then 0.05 s: its toe's slide, its turn, its joint contacts and the loaded ones' place
behind the toe disc (docs/notebook/2026-12-05_limit_equilibrium_strength_reduction.md).

    ./yade -x -n -j1 calibration/block_on_incline/band.py [rmax [bond_gap]]     # 0.004 m, 0.05 Rmin
"""
import sys

from yade import O
from yade.wrapper import SmoothJointPhys

from examples import params
from toppling.load import tilting
from toppling.models import incline
from toppling.run.steps import run_steps, steps_in

rmax = float(sys.argv[1]) if len(sys.argv) > 1 else 0.004
bond_gap = float(sys.argv[2]) if len(sys.argv) > 2 else incline.BOND_GAP
block = incline.build(0.09, 0.2, rmax / params.PACKING_R_RATIO, rmax, params.TABLE_5_6_ROCK, 20.0, bond_gap=bond_gap)
incline.settle(0.05)
tilting.set_tilt(30.0)
members, start = set(block.block), O.time
toe_x = O.bodies[block.toe].state.pos[0]
for interval in [0.01] * 5 + [0.05] * 7:
    run_steps(steps_in(interval))
    contacts = [i for i in O.interactions if isinstance(i.phys, SmoothJointPhys)]
    loaded = sorted(round(1e3 * (O.bodies[i.id1 if i.id1 in members else i.id2].state.pos[0]
                                 - O.bodies[block.toe].state.pos[0])) for i in contacts if i.phys.jointNormalForce > 0)
    print(f"t {O.time - start:.2f} s: slid {1e3 * (O.bodies[block.toe].state.pos[0] - toe_x):.1f} mm, turned "
          f"{incline.mean_spin_deg(block.block):.1f} deg, {len(contacts)} joint contacts, loaded ones at {loaded} mm "
          "from the toe disc", flush=True)
