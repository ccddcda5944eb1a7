"""Does one Ihlara column stand alone? Ignimbrite (Table 5-12) 3.5 m wide and ``height`` m tall on
tuff, a bedding joint of Table 5-13 between them; bonded and settled with local damping 0.7, jointed,
then run undamped, printing every 0.1 s the column's tilt (its top discs' median x against its
foot's) and their median displacement. Arguments, each 0 or 1 unless said:
``turn`` 0 keeps the joint normals where they were installed (Law2's turnInterval out of reach);
``ks`` [N/m³] replaces Table 5-13's shear stiffness (0: Table 5-13's); ``soft``: the tuff 10 m deep,
bonded and held at its base and sides, the column's top 5 m ash (as the cliff's), else a fixed tuff
slab 2.5 m deep; ``edge``: the bedding ends at the column's face; ``placed``: the column stands where
the cliff's column 1 does, 28 m of tuff behind it and 6.5 m in front, the front side free.

    ./yade -x -n -j1 calibration/ihlara/lone_column.py [height [turn [ks [soft [edge [placed]]]]]]
"""
import math
import statistics
import sys

from yade import O
from yade.wrapper import JointSetGeometry, Law2_ScGeom_SmoothJointPhys_SmoothJoint, ParallelBondMat

from examples import params
from toppling.build import boundary, engines, joints
from toppling.build.discs import add_discs
from toppling.models.tilting_table import JointMaterial, bond_in_scene, packed_discs
from toppling.run.steps import run_steps, steps_in

height = float(sys.argv[1]) if len(sys.argv) > 1 else 30.0
turn = sys.argv[2] != "0" if len(sys.argv) > 2 else True
kn, ks, mu = params.TABLE_5_13["bedding"]
ks = float(sys.argv[3]) if len(sys.argv) > 3 and float(sys.argv[3]) > 0 else ks
soft, edge, placed = (len(sys.argv) > k and sys.argv[k] == "1" for k in (4, 5, 6))
discs = params.TABLE_5_12_DISCS
width, depth = 3.5, (10.0 if soft else 2.5)
behind, ahead = (28.0, 6.5) if placed else ((17.0, 17.0) if soft else (2.0, 2.0))

section = [(-behind, -depth), (width + ahead, -depth), (width + ahead, 0), (width, 0), (width, height), (0, height),
           (0, 0), (-behind, 0)]
packed = packed_discs(section, discs["rmin"], discs["rmax"], 0.18, 1, False)
ash = params.IHLARA_SECTION["ignimbrite"] if soft else height  # the ash cap above the ignimbrite's 25 m
column = add_discs([d for d in packed if 0 <= d[1] < ash], ParallelBondMat(**params.TABLE_5_12["ignimbrite"]))
column += add_discs([d for d in packed if d[1] >= ash], ParallelBondMat(**params.TABLE_5_12["ash"]))
base = add_discs([d for d in packed if d[1] < 0], ParallelBondMat(**params.TABLE_5_12["tuff"]))
ids = bond_in_scene(column + base, discs["bond_gap"], 0.7, 0.8)
if soft:
    held = [b for b in base if b in ids]
    boundary.fix(boundary.near([((-behind, -depth), (width + ahead, -depth))], discs["rmax"], held), "xy")
    sides = [((-behind, -depth), (-behind, 0))] + ([] if placed else [((width + ahead, -depth), (width + ahead, 0))])
    boundary.fix(boundary.near(sides, discs["rmax"], held), "x")
else:
    boundary.fix([b for b in base if b in ids], "xy")
run_steps(steps_in(0.5))
engines.set_local_damping(0.0)
bedding = JointSetGeometry(dip=0, segmentStarts=[(-behind, 0.0)], segmentEnds=[(width if edge else width + ahead, 0.0)])
joints.install_joints([(bedding, JointMaterial(kn, mu, ks).material(params.TABLE_5_13["gap"], 1.0))],
                      lo=(-behind - 1, -depth - 1), hi=(width + ahead + 1, height + 1))
if not turn:
    engines.functor(Law2_ScGeom_SmoothJointPhys_SmoothJoint).turnInterval = 2**30
members = [b for b in column if b in ids]
for b in members:
    O.bodies[b].state.refPos = O.bodies[b].state.pos
top = [b for b in members if O.bodies[b].state.pos[1] > height - 1.0]
low = [b for b in members if O.bodies[b].state.pos[1] < 1.0]


def median_x(group: list[int]) -> float:
    return statistics.median(O.bodies[b].state.displ()[0] for b in group)


print(f"lone column {width} x {height} m, {len(members)} discs, joint kn {kn:g} ks {ks:g} N/m3, mu {mu}, "
      f"normals {'turn' if turn else 'fixed'}", flush=True)
for _ in range(15):
    run_steps(steps_in(0.1))
    tilt = math.degrees(math.atan2(median_x(top) - median_x(low), height - 1.0))
    print(f"t {O.time:.2f} s: tilt {tilt:+.3f}°, top x {1e3 * median_x(top):+.1f} mm, "
          f"foot x {1e3 * median_x(low):+.1f} mm", flush=True)
