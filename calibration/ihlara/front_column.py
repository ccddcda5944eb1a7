"""Why the Ihlara cliff's front column turns out (docs/cases/ihlara.md): the cliff (no weathered
zone by default) settled with local damping, jointed, then run undamped, printing every 0.05 s the
normal force across the first vertical joint, what the bedding carries under column 1 (its normal
force, the share under the column's front half, 0.53 of it: the friction it can give, its shear,
its contacts), column 1's intact bonds and the median displacement of its top and foot discs (loose
discs aside); at the end its discs' median displacement by height. Options: ``alone``: the columns
behind it taken away before the cliff settles (nothing pushes it); ``fixed``: the joint normals keep
their installed direction (Law2's turnInterval out of reach); ``closure``: joint contacts made
later start with their faces' closure (JointSystem.faceClosure); ``seed=N``: the packing (1 by
default); a number: how many reports.

    ./yade -x -n -j1 calibration/ihlara/front_column.py [intact|weathered|eroded [alone] [fixed] [closure] [seed=N] [reports]]
"""
import math
import statistics
import sys
from types import SimpleNamespace

from yade import O
from yade.wrapper import Law2_ScGeom_SmoothJointPhys_SmoothJoint, SmoothJointPhys

from examples import params
from toppling.build import engines, joints
from toppling.models import layered_cliff
from toppling.run.steps import run_steps, steps_in

case = sys.argv[1] if len(sys.argv) > 1 else "intact"
alone, fixed, closure = "alone" in sys.argv[2:], "fixed" in sys.argv[2:], "closure" in sys.argv[2:]
reports = int(sys.argv[-1]) if sys.argv[-1].isdigit() else 12
seed = next((int(a[5:]) for a in sys.argv[2:] if a.startswith("seed=")), 1)
cliff = layered_cliff.ihlara_from_params(SimpleNamespace(**{**params.IHLARA, "case": case, "seed": seed}), params)
face, width = cliff.face_x, cliff.column_width
column_1 = (face - width, face)


def in_column_1(x: float) -> bool:
    return column_1[0] <= x <= column_1[1]


def joint_forces() -> dict[str, float]:
    """Across the first vertical joint and along the bedding under column 1 [N/m], now."""
    f = dict(push=0.0, base=0.0, front=0.0, shear=0.0, tilt=0.0, contacts=0, slipping=0)
    for i in O.interactions:
        if not isinstance(i.phys, SmoothJointPhys):
            continue
        x = 0.5 * (O.bodies[i.id1].state.pos[0] + O.bodies[i.id2].state.pos[0])
        if i.phys.jointSet == 0 and abs(x - column_1[0]) < 0.5:
            f["push"] += i.phys.jointNormalForce
        if i.phys.jointSet == 1 and in_column_1(x):
            n = i.phys.jointNormal
            f["base"] += i.phys.jointNormalForce
            f["front"] += i.phys.jointNormalForce if x > column_1[0] + 0.5 * width else 0.0
            f["shear"] += i.phys.jointShearForce * -abs(n[1])  # its x-component on the upper disc
            f["tilt"] += math.degrees(math.atan2(n[0], abs(n[1])))
            f["contacts"] += 1
            f["slipping"] += i.phys.isSlipping
    return f


def report(label: str, column: list[int]) -> None:
    """``column``: column 1's discs (ids), chosen when the joints were installed."""
    f, members = joint_forces(), set(column)
    bonds = sum(1 for i in O.interactions
                if i.id1 in members and i.id2 in members and getattr(i.phys, "bondState", 0) == 1)
    states = [O.bodies[b].state for b in column]
    top = [s.displ() for s in states if s.refPos[1] > cliff.height - 1]
    foot = [s.displ() for s in states if s.refPos[1] < 0.5]
    moved = lambda group: ", ".join(f"{k} {1e3 * statistics.median(v[j] for v in group):+.1f}"  # noqa: E731
                                    for j, k in enumerate("xy"))
    print(f"{label}: t {O.time:.2f} s, across joint 1 {f['push'] / 1e6:.3f} MN/m; bedding under column 1 "
          f"{f['base'] / 1e6:.3f} MN/m ({f['front'] / max(f['base'], 1e-9):.0%} under its front half, x 0.53 = "
          f"{0.53 * f['base'] / 1e6:.3f}), shear {f['shear'] / 1e6:+.3f} MN/m on the column, {f['slipping']} of "
          f"{f['contacts']} contacts slipping, normals tilted {f['tilt'] / max(f['contacts'], 1):+.2f}°; "
          f"{bonds} intact bonds; its top moved {moved(top)} mm, its foot {moved(foot)} mm", flush=True)


def profile(column: list[int]) -> None:
    """How column 1 moved, by its discs' height when jointed: the median of each 3 m band."""
    for low in range(0, 30, 3):
        band = [O.bodies[b].state.displ() for b in column if low <= O.bodies[b].state.refPos[1] < low + 3]
        print(f"height {low:2d}-{low + 3:2d} m: {len(band)} discs, median sink "
              f"{-1e3 * statistics.median(d[1] for d in band):.1f} mm, median x "
              f"{1e3 * statistics.median(d[0] for d in band):+.1f} mm")


cliff.build()
if alone:
    for b in list(O.bodies):
        if b.state.pos[1] > 0 and b.state.pos[0] < column_1[0]:
            O.bodies.erase(b.id)
engines.set_local_damping(params.IHLARA["settle_damping"])
run_steps(steps_in(0.6))
engines.set_local_damping(0.0)
cliff.settled()
joints.rock_functor().joints.faceClosure = closure
if fixed:
    engines.functor(Law2_ScGeom_SmoothJointPhys_SmoothJoint).turnInterval = 2**30
column = [b.id for b in O.bodies if b is not None and in_column_1(b.state.pos[0]) and b.state.pos[1] > 0]
for b in column:
    O.bodies[b].state.refPos = O.bodies[b].state.pos
report("jointed", column)
for _ in range(reports):
    run_steps(steps_in(0.05))
    report("then", column)
profile(column)
