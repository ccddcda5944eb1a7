"""Why the Ihlara cliff's front column turns out (docs/cases/ihlara.md): the control (no weathered
zone) settled with local damping, jointed, then run undamped, printing every 0.1 s the normal
force across the first vertical joint, the bedding's normal force under column 1 (and 0.53 of
it, the friction it can give), column 1's weight, and the mean x-displacement of its top and foot.

    ./yade -x -n -j1 calibration/ihlara/front_column.py [case]     # case: intact (default), weathered, eroded
"""
import sys
from types import SimpleNamespace

from yade import O
from yade.wrapper import SmoothJointPhys

from examples import params
from toppling.build import engines
from toppling.models import layered_cliff
from toppling.run.steps import run_steps, steps_in

case = sys.argv[1] if len(sys.argv) > 1 else "intact"
cliff = layered_cliff.ihlara_from_params(SimpleNamespace(**{**params.IHLARA, "case": case}), params)
face, width = cliff.face_x, cliff.column_width
column_1 = (face - width, face)


def in_column_1(x: float) -> bool:
    return column_1[0] <= x <= column_1[1]


def report(label: str) -> None:
    push = base = 0.0
    for i in O.interactions:
        if isinstance(i.phys, SmoothJointPhys):
            x = 0.5 * (O.bodies[i.id1].state.pos[0] + O.bodies[i.id2].state.pos[0])
            if i.phys.jointSet == 0 and abs(x - column_1[0]) < 0.5:
                push += i.phys.jointNormalForce
            if i.phys.jointSet == 1 and in_column_1(x):
                base += i.phys.jointNormalForce
    bodies = [b for b in O.bodies if b is not None and in_column_1(b.state.pos[0]) and b.state.pos[1] > 0]
    weight = sum(b.state.mass for b in bodies) * engines.G
    top = [b.state.displ()[0] for b in bodies if b.state.pos[1] > cliff.height - 1]
    foot = [b.state.displ()[0] for b in bodies if b.state.pos[1] < 0.5]
    print(f"{label}: t {O.time:.2f} s, across joint 1 {push / 1e6:.3f} MN/m, bedding under column 1 {base / 1e6:.3f} "
          f"MN/m (x 0.53 = {0.53 * base / 1e6:.3f}), column 1 weighs {weight / 1e6:.3f} MN/m, its top moved "
          f"{1e3 * sum(top) / len(top):.1f} mm, its foot {1e3 * sum(foot) / len(foot):.1f} mm", flush=True)


cliff.build()
engines.set_local_damping(params.IHLARA["settle_damping"])
run_steps(steps_in(0.6))
engines.set_local_damping(0.0)
cliff.settled()
report("jointed")
for _ in range(6):
    run_steps(steps_in(0.1))
    report("then")
