"""What turns a block sliding in Sagaseta's band: a block (20 x 40 cm: b/h 0.5) on the incline at
30 deg, settled level, tilted at once; every 0.01 s its slide, how far its centre of mass has sunk
into the base, its turn and spin, and the joint's forces on it (normal N, shear S), the reaction's
place along the base from the centre of mass, the loaded joint contacts, and the moments of the
joint's normal and shear forces about the centre of mass beside the moment of every force on the
block (docs/verification.md).

    ./yade -x -n -j1 calibration/block_on_incline/moments.py [phi [rmax [chunks of 0.01 s [b [h]]]]]
    # defaults: 10 deg, 0.012 m, 30, 0.2 m, 0.4 m
"""
import sys

import numpy as np
from yade import O
from yade.wrapper import SmoothJointPhys

from examples import params
from toppling.load import tilting
from toppling.models import incline
from toppling.run.steps import run_steps, steps_in

phi = float(sys.argv[1]) if len(sys.argv) > 1 else 10.0
rmax = float(sys.argv[2]) if len(sys.argv) > 2 else 0.012
chunks = int(sys.argv[3]) if len(sys.argv) > 3 else 30
b = float(sys.argv[4]) if len(sys.argv) > 4 else 0.2
h = float(sys.argv[5]) if len(sys.argv) > 5 else 0.4
block = incline.build(b, h, rmax / params.PACKING_R_RATIO, rmax, params.TABLE_5_6_ROCK, phi)
incline.settle(0.05)
members = set(block.block)


def plane(v) -> np.ndarray:
    return np.array((v[0], v[1]))


def centre_of_mass() -> np.ndarray:
    mass = np.array([O.bodies[i].state.mass for i in block.block])
    return (mass[:, None] * np.array([plane(O.bodies[i].state.pos) for i in block.block])).sum(0) / mass.sum()


def cross(r: np.ndarray, f: np.ndarray) -> float:
    return float(r[0] * f[1] - r[1] * f[0])


start = centre_of_mass()
tilting.set_tilt(30.0)
for k in range(chunks):
    run_steps(steps_in(0.01))
    centre = centre_of_mass()
    normal_moment = shear_moment = normal = shear = lever = 0.0
    loaded = 0
    for i in O.interactions:
        if not isinstance(i.phys, SmoothJointPhys) or (i.id1 in members) == (i.id2 in members):
            continue
        sign = 1.0 if i.id2 in members else -1.0  # the physics holds the force on body 2
        fn, fs = sign * plane(i.phys.normalForce), sign * plane(i.phys.shearForce)
        r = plane(i.geom.contactPoint) - centre
        normal_moment, shear_moment = normal_moment + cross(r, fn), shear_moment + cross(r, fs)
        normal, shear, lever = normal + fn[1], shear + fs[0], lever + fn[1] * r[0]
        loaded += i.phys.jointNormalForce > 0
    every = sum(cross(plane(O.bodies[i].state.pos) - centre, plane(O.forces.f(i))) + O.forces.t(i)[2] for i in block.block)
    spin = np.mean([O.bodies[i].state.angVel[2] for i in block.block])
    print(f"t {0.01 * (k + 1):.2f} s: slid {1e3 * (centre[0] - start[0]):6.1f} mm, sank {1e6 * (start[1] - centre[1]):6.0f} um, "
          f"turn {incline.mean_spin_deg(block.block):6.2f} deg, spin {spin:6.3f} rad/s; N {normal:7.1f} N, S/N "
          f"{shear / normal if normal else 0:.3f}, reaction at {1e3 * lever / normal if normal else 0:6.1f} mm, {loaded:2d} "
          f"loaded; moments about the centre of mass: normal {normal_moment:7.2f}, shear {shear_moment:7.2f}, all "
          f"{every:7.2f} N m", flush=True)
