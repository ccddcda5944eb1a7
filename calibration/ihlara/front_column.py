"""Why the Ihlara cliff's front column turns out (docs/cases/ihlara.md): the control (no weathered
zone) settled with local damping, jointed, then run undamped, printing every 0.1 s the normal
force across the first vertical joint, the bedding's normal force under column 1 (and 0.53 of
it, the friction it can give), column 1's weight, and the median displacement of its top and foot (loose discs aside), and at the end its
discs' median displacement by height.
With ``alone`` the columns behind it are taken away before the cliff settles (nothing pushes it);
with ``fixed`` the joint normals keep their installed direction (Law2's turnInterval out of reach); with
``closure`` joint contacts made later start with their faces' closure (JointSystem.faceClosure).

    ./yade -x -n -j1 calibration/ihlara/front_column.py [case [alone] [fixed] [closure] [reports]]   # case: intact (default), weathered, eroded
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
cliff = layered_cliff.ihlara_from_params(SimpleNamespace(**{**params.IHLARA, "case": case}), params)
face, width = cliff.face_x, cliff.column_width
column_1 = (face - width, face)


def in_column_1(x: float) -> bool:
    return column_1[0] <= x <= column_1[1]


def report(label: str, column: list[int]) -> None:
    """``column``: column 1's discs (ids), chosen when the joints were installed."""
    push = base = shear = tilt = front = 0.0
    contacts = slipping = 0
    for i in O.interactions:
        if isinstance(i.phys, SmoothJointPhys):
            x = 0.5 * (O.bodies[i.id1].state.pos[0] + O.bodies[i.id2].state.pos[0])
            if i.phys.jointSet == 0 and abs(x - column_1[0]) < 0.5:
                push += i.phys.jointNormalForce
            if i.phys.jointSet == 1 and in_column_1(x):
                n = i.phys.jointNormal
                base += i.phys.jointNormalForce
                front += i.phys.jointNormalForce if x > column_1[0] + 0.5 * width else 0.0
                shear += i.phys.jointShearForce * -n[1] * (1 if n[1] > 0 else -1)  # x-component on the upper disc
                tilt += math.degrees(math.atan2(n[0], abs(n[1])))
                contacts += 1
                slipping += i.phys.isSlipping
    members = set(column)
    bonds = sum(1 for i in O.interactions if i.id1 in members and i.id2 in members and getattr(i.phys, "bondState", 0) == 1)
    bodies = [O.bodies[b] for b in column]
    weight = sum(b.state.mass for b in bodies) * engines.G
    top = [b.state.displ() for b in bodies if b.state.refPos[1] > cliff.height - 1]
    foot = [b.state.displ() for b in bodies if b.state.refPos[1] < 0.5]
    median = lambda values, k: 1e3 * statistics.median(v[k] for v in values)  # noqa: E731  (loose discs aside)
    print(f"{label}: t {O.time:.2f} s, across joint 1 {push / 1e6:.3f} MN/m, bedding under column 1 {base / 1e6:.3f} "
          f"MN/m ({front / max(base, 1e-9):.0%} under its front half; x 0.53 = {0.53 * base / 1e6:.3f}; shear {shear / 1e6:+.3f} MN/m on the column, {slipping} of "
          f"{contacts} contacts slipping, normals tilted {tilt / max(contacts, 1):+.2f}° on average), column 1 weighs "
          f"{weight / 1e6:.3f} MN/m, {bonds} intact bonds; its top (median) moved x {median(top, 0):+.1f} y {median(top, 1):+.1f} mm, its foot "
          f"x {median(foot, 0):+.1f} y {median(foot, 1):+.1f} mm", flush=True)


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
for _ in range(int(sys.argv[-1]) if sys.argv[-1].isdigit() else 12):
    run_steps(steps_in(0.05))
    report("then", column)
for low in range(0, 30, 3):  # how column 1 moved, by height when jointed
    band = [O.bodies[b].state for b in column if low <= O.bodies[b].state.refPos[1] < low + 3]
    print(f"height {low:2d}-{low + 3:2d} m: {len(band)} discs, median sink {-1e3 * statistics.median(s.displ()[1] for s in band):.1f} "
          f"mm, median x {1e3 * statistics.median(s.displ()[0] for s in band):+.1f} mm")
