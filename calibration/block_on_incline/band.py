"""A block in Sagaseta's band (tan φ ≤ b/h < tan α: it should slide upright) and the joint contacts
that carry it: a 9 × 20 cm block, α 30°, settled on the level table, then tilted. Prints, at rest,
the joint contacts (place behind the toe disc, normal force) and how far behind the block's toe
edge the foremost one lies against the margin (b − h tan φ)/2 within which a sliding block's base
reaction must fall; then every 0.01 s, then 0.05 s: its toe's slide, its turn, its joint contacts
and the loaded ones' place behind the toe disc (docs/verification.md).

    ./yade -x -n -j1 calibration/block_on_incline/band.py [rmax [bond_gap [phi [joint_stiffness_scale [ramp [face_closure [limit]]]]]]]
    # defaults: 0.004 m, 0.05 Rmin, 20 deg, 1, 0 s (tilted at once; else over ramp seconds, the clock
    # starting when it is done), 0 (1: new joint contacts start with the faces' closure), JointSystem's
    # faceClosureLimit
"""
import math
import sys

from yade import O
from yade.wrapper import SmoothJointPhys

from examples import params
from toppling.build import joints
from toppling.load import tilting
from toppling.models import incline
from toppling.run.steps import run_steps, steps_in

rmax = float(sys.argv[1]) if len(sys.argv) > 1 else 0.004
bond_gap = float(sys.argv[2]) if len(sys.argv) > 2 else incline.BOND_GAP
phi = float(sys.argv[3]) if len(sys.argv) > 3 else 20.0
scale = float(sys.argv[4]) if len(sys.argv) > 4 else 1.0
ramp = float(sys.argv[5]) if len(sys.argv) > 5 else 0.0
face_closure = len(sys.argv) > 6 and sys.argv[6] == "1"
limit = float(sys.argv[7]) if len(sys.argv) > 7 else None
b, h = 0.09, 0.2
block = incline.build(b, h, rmax / params.PACKING_R_RATIO, rmax, params.TABLE_5_6_ROCK, phi, bond_gap=bond_gap,
                      joint_stiffness_scale=scale, face_closure=face_closure)
if limit is not None:
    joints.rock_functor().joints.faceClosureLimit = limit
incline.settle(0.05)
members = set(block.block)
toe_x = O.bodies[block.toe].state.pos[0]
edge = max(O.bodies[i].state.pos[0] + O.bodies[i].shape.radius for i in block.block)
at_rest = sorted((O.bodies[i.id1 if i.id1 in members else i.id2].state.pos[0] - toe_x, i.phys.jointNormalForce)
                 for i in O.interactions if isinstance(i.phys, SmoothJointPhys))
print("at rest, joint contacts (mm behind the toe disc, N):", [(round(1e3 * x, 1), round(f, 1)) for x, f in at_rest])
print(f"foremost joint contact {1e3 * (edge - toe_x - at_rest[-1][0]):.1f} mm behind the toe edge; a sliding block's "
      f"reaction lies {1e3 * (b - h * math.tan(math.radians(phi))) / 2:.1f} mm behind it", flush=True)
if ramp > 0:
    tilting.ramp(0.0, 30.0, ramp)
    print(f"tilted over {ramp:g} s: slid {1e3 * (O.bodies[block.toe].state.pos[0] - toe_x):.1f} mm, turned "
          f"{incline.mean_spin_deg(block.block):.2f} deg", flush=True)
tilting.set_tilt(30.0)
start = O.time
for interval in [0.01] * 5 + [0.05] * 7:
    run_steps(steps_in(interval))
    contacts = [i for i in O.interactions if isinstance(i.phys, SmoothJointPhys)]
    loaded = sorted(round(1e3 * (O.bodies[i.id1 if i.id1 in members else i.id2].state.pos[0]
                                 - O.bodies[block.toe].state.pos[0])) for i in contacts if i.phys.jointNormalForce > 0)
    print(f"t {O.time - start:.2f} s: slid {1e3 * (O.bodies[block.toe].state.pos[0] - toe_x):.1f} mm, turned "
          f"{incline.mean_spin_deg(block.block):.1f} deg, {len(contacts)} joint contacts, loaded ones at {loaded} mm "
          "from the toe disc", flush=True)
