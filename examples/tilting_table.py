"""Tilting-table tests of Amini et al. (2015), thesis §5.2: block-flexural toppling of columns.

Reconstruction (the thesis' Figs 5-3...5-6 are not in its text), in the table frame (table
surface y = 0, columns standing along +y, the toe at the right, the slope to the left):

* Columns of 5 cm wide blocks (10 x 5 x 4.7 cm: 10 cm along the column, 4.7 cm the disc
  thickness t) standing upright on the table. Upright, because §5.3.1 says the ideal model
  tilted by its failure angle 35 deg is the equivalent slope with joints dipping delta = 55 deg
  = 90 - 35 into the slope.
* The same rotation fixes the outline: the face is at theta = 98 deg after tilting, i.e. the
  column tops rise from the toe into the slope at 98 - 35 - 90 + 180 - 180 = 47 deg to the
  table (the face line runs at 133 deg in the table frame), and the upper surface at
  beta = 8 deg after tilting falls away from the crest into the slope at 35 - 8 = 27 deg to the
  table. The crest is where the tilted model is H = 47.39 cm high (Table 5-2), 35.0 cm above
  the table. The number of columns then follows from the size of the model: 6270 discs of
  R 1-4 mm at porosity 0.12 cover 0.157 m2, which the outline reaches with 14.6 columns -> 15
  columns (0.75 m), the back column 14.4 cm high. The thesis' monitoring points go up to
  column O-15, which agrees.
* Rectangular blocks have flat tops: each column's top is at the outline's height at the
  column centre (a stepped face).
* Main joints between all columns (Table 5-3 "joint"). Ideal arrangement: one cross joint
  (Table 5-3 "base joint") in every other column starting at the toe, the blocky column's
  "joint base" (§5.3.2) that leaves it "divided into two parts" (§5.2.4.1); the columns between
  are continuous ("flexural failure potential due to its lack of joint base"). One per column,
  because the thesis' variants of this model (Tables 5-7, 5-8) merge pairs of base joints or
  add a second, parallel base-joint set: the base model has one row of them. That row lies on a
  plane rising from the toe at DESIGN_PLANE_DEG = 15 deg to the table, as in the slope model
  the arrangement copies (Amini et al. 2012, Figs 5-13/5-14: blocky columns rest on the
  overall failure plane, flexural columns cross it). Measured at R 2-8 mm, other layouts: the
  blocky columns standing on the table fail at 36 deg along a surface at 36 deg; joints every
  10 cm above the base joint (stacked blocks) let the top blocks topple on their own, failure
  points at the upper joints (phi 45 deg). Random arrangement: blocks 10 cm long stacked in
  every column with a random offset (seeded by `layout_seed`, apart from the packing's `seed`:
  the thesis has one random arrangement, packed once). Cross joints only where the piece above
  leans on the downhill neighbour column over at least a quarter of a block (so none in the toe
  column), and none that leaves a top piece shorter than half a block: a block free of its
  neighbour, touching it at a corner, or a thin sliver on a mu 0.23 joint slides off at 13 deg
  plus what the main joints' friction holds, long before the slope topples (measured: the top
  block of column G-7, touching F-6 over 8 mm, slid at 28 deg, and so did a 4 cm sliver on G-7).
  These rules keep 24 of the 30, 35 and 35 block boundaries of layouts 1-3 (the example prints the
  count); `cut_rules` = 0 turns them off, every block boundary a joint (default 1). `toe_column`
  = 0 takes the toe column A-1's discs out before bonding, the slope as the R 2-8 mm packing leaves
  it (no bonded disc in A-1; default 1). Measured at R 1-4 mm: docs/tilting_table.md, "Without the
  layout's rules, and to 31 deg".
  Neither rule leaves a cut in the toe column A-1; `sliding_toe` = 1 keeps its cuts (the ideal
  model's base joint at 0.67 cm: the thesis' sliding zone at the toe, and Table 5-8's case III puts
  a base joint there "to provide the required deformation in the slope to fail"). Measured at
  R 1-4 mm (docs/tilting_table.md, "A sliding toe"): the ideal model at 85 kPa fails at 34 deg
  with it as without it, at Table 5-2's 209 kPa it stands to 44 deg, and the random layout 3 stands
  to 25 deg either way; default 0.
* Contacts that form after the joints are installed are smooth joints between different pieces
  of rock (`joint_pieces` = 1, default): a block sliding on a cross joint meets the rock below
  through the joint, not as interlocking discs. 0 tells blocks apart by the main joints only, as
  every table line before 123 ran (docs/tilting_table.md, "Joints between pieces of rock").
* Micro-parameters: Tables 5-2 and 5-3, except the porosity (0.18: the packer does not lock in
  overlap, see README) and what the calibration below changes.
* `shrink_overlaps` = 1 shrinks each disc by half its largest overlap before bonding. The
  relaxed packing still holds overlaps up to 3.6 % of Rmin (R 1-4 mm, seed 1; 1 % of the
  overlapping pairs above 1.3 %), whose contact force a stress-free bond must take in tension:
  at 50 kPa that broke 10 bonds in the first 0.4 ms, before gravity had loaded anything. 0 bonds
  the packing as it is (the table's rows run before this option keep 0, so they reproduce).

Calibration (the issue allows joint friction and bond strengths within the thesis' ranges;
`bond_tensile_strength`, `main_joint_friction`, `base_joint_friction`, 0 = the tables' value).
Ideal model, R 2-8 mm, failure tilt against bond tensile strength (README): 60 kPa <= 26 deg,
100 and 110 kPa 32 deg, 120 kPa 44 deg, 130 kPa standing at 38 deg, 159 kPa (Table 5-2's
random-model value) none up to 44 deg. At 32 deg the toe columns collapse; up to 110 kPa the
collapse spreads into the slope, from 120 kPa it comes to rest (18.7 mm), and so do the next
ones at 36 and 40 deg, so at this resolution none of these strengths fails near 35 deg. The
ideal rows of tilting_table.table use 110 kPa, the strongest tested that fails at the first
collapse (32 deg, inside 35 +- 3; packed with seed 2 instead of 1 it fails at 38 deg, so the
packing counts as much as the strength). The random model keeps Table 5-2 (159 kPa: fails at
23 deg, at 21 deg by the stage time limit with 1 deg steps and timestep_safety 0.8); its joint
frictions are at the range's bottom already, and of the bond strengths tried 100 kPa fails at
15 deg, 120 and 130 kPa have a local collapse at 17 deg that comes to rest, and 130 kPa fails at
25 deg (README). All of these ran with local damping 0.7 (see Damping). At the thesis' R 1-4 mm
(joints softened, overlaps shrunk, fail_columns 2; lines 53-68) 55 kPa fails at 36 deg with
seed 1 but anywhere in 20-42 deg over nine seeds, and at R 1-2.5 mm at 38-44 deg over four.
Without local damping (lines 84-94, 101-104) 85 kPa fails R 1-4 mm at 34, 24, 28, 34, 34, <= 26,
34, <= 26, 32 deg over seeds 1-9 and R 1-2.5 mm at 36, 34, 32, 38, 42 deg over seeds 1-5: in
the stage in which the most stressed bond reaches the strength (docs/tilting_table.md, "Without
local damping"). At R 1-4 mm the random model with blocks told apart by the main joints only
(lines 105-109, 120, 121) stands to 25 deg at 159 kPa, at 65 kPa (159 scaled as the ideal model's
209 -> 85) and with 10 times stiffer joints alike, and layout 1 to 31 deg with or without the
layout's rules. Between pieces (`joint_pieces` 1) layout 1 fails at 35 deg through its rock from
the toe with the rules (line 123) and at 19 deg without them (`cut_rules` 0, line 133), its top
blocks sliding off their cross joints (docs/tilting_table.md, "The random model at R 1-4 mm
between pieces"). A run whose bonds
do not break (209 kPa, lines 111, 114-117) bounds the failure tilt of every weaker strength from
below: the slope fails in the stage in which the second most stressed bond reaches the strength,
or one or two stages later (docs/tilting_table.md, "One run with bonds that do not break").

Loading: the discs within Rmax of the table are fixed in x and y (§5.2.4.2); gravity is turned
by the tilt (Fig 5-7). The model first comes to rest on the level table, then the tilt rises
steadily at `tilt_rate` deg/s to `start_tilt` (a tilt switched on at once loads the columns
dynamically, up to twice their static stress; `start_tilt` 0 skips it), then by `step` degrees
per stage, each step at once or, with `stage_rate` > 0, at that many deg/s. Each stage runs in
chunks of `chunk` seconds until

* equilibrium: the fastest column top (the centroid of the bonded discs within 2 Rmax of the
  top: a loose disc rattling is not a column moving) moves slower than `rest_speed`, or
* failure: the motion does not die out: a column top is still moving faster than `rest_speed`
  after `max_stage_time` (2 s: the columns' first bending period is ~0.2 s and local damping
  needs a few, but blocks settling onto their neighbours creep for longer: measured at R 2-8
  mm, the random model at 15 deg came to rest 0.7 s into the stage, after a 0.6 s limit had
  called it failed, and at 19 deg about 1.5 s into it, after a 1 s limit had called it failed:
  continued, its kinetic energy fell below 1e-9 J) and has moved further than `rest_speed`
  times the stage's time (less is a column ringing in place, which without local damping can
  go on for seconds: the random model at R 2-8 mm, packing seed 3, "failed" at 17 deg by the
  time limit with its toe column 0.6 mm from where the stage began), or `fail_columns` column
  tops have moved more than `fail_displacement` (one column width: toppled off their
  neighbours, no need to wait).
  With `fail_columns` 2 a column that topples off alone (at R 1-4 mm the toe column A-1, 2.7 cm
  high, once its root has cracked: the rest of the slope came to rest behind it, and the analysis
  finds no surface) is gone: the stage's log line and `gone` key name it, and the others decide
  (`moved_mm` is then theirs). A local collapse that comes to rest is not failure: measured at
  R 2-8 mm and 159 kPa, the toe columns of the ideal model moved more than 5 mm at 36 deg,
  breaking 8 bonds, and were at rest 0.76 s into the stage; with a 5 mm threshold (before) that
  stage counted as the failure.

Damping: the thesis' only damping is viscous, in the contacts and bonds (Table 5-2's critical
damping ratios 0.13 and 0.2, always on). `damping` adds NewtonIntegrator's local damping while
the table tilts, `settle_damping` while the model comes to rest on the level table (0.7, a way
to the initial equilibrium, which the thesis reaches by its own means, §5.2.4.1). Local damping
takes up to `damping` times the force off every disc, so it also brakes a collapse: measured at
R 2-8 mm (lines 31, 75-79), the first collapse (32 deg) comes to rest under 0.7 at 120 and
130 kPa (then failure at 42 deg, or none to 44) and is the failure without it at 110-130 kPa
alike, and the R 1-2.5 mm slopes at 45-75 kPa with 0.7 crack and come to rest to 42-44 deg
(docs/tilting_table.md, "Local damping"). `damping` is 0 by default, as in the thesis (lines
1-72 of the table used 0.7; 73-75, 77 and 79 onwards 0). Without local damping a step of the
tilt applied at once overshoots its static load (see Loading), so each step is ramped by
default (`stage_rate` 10 deg/s; lines 1-81 stepped at once).

Time step: GlobalStiffnessTimeStepper's, dt = sqrt(2) `timestep_safety` min sqrt(m/K) over the
discs (K: the stiffness of their bonds, contacts and joints), updated every 100 steps; Table 5-3's
joints, 150 times stiffer than the bonds, set it. 0.5 keeps a margin for joint contacts that close
between two updates; YADE's default 0.8 takes 1.6 times fewer steps per simulated second.
Measured at R 2-8 mm, 110 kPa (table lines 5 and 18, side by side): the same stages, failure tilt
(32 deg), zones (B-2 to G-7 toppling), S/H and T/H (0.21), 29 / 32 tensile and 5 shear breaks,
four of the six failure points within 6.5 mm; the toe columns B-2 and C-3 break 5 and 4 cm lower
at 0.8, which turns phi from 8.1 to 18.5 deg (README: the same two points move between bond
strengths). The calibrated rows keep 0.5.

Joint stiffness: `joint_stiffness_scale` multiplies both of Table 5-3's joint stiffnesses (1: the
table). The joints only need to be stiff next to the rock: under the 47 cm of rock (13 kPa) Table
5-3's joints close by 0.01-0.1 um, and at 0.01 times by 1-11 um, still a tenth of their 0.1 mm gap
or less and far below the 0.4 mm the rock itself shortens under that load (Ec 15 MPa), while the
time step grows 7.5 times. Measured at R 2-8 mm, 110 kPa (table lines 5, 18, 21, 22 against 37,
31, 35, 36): failure tilt the same for seeds 1 (at both time-step safeties) and 2, 2 deg lower for
seed 3 (36 against 38); phi within 1.2 deg, except seed 1 at safety 0.5 (17.5 against 8.1: its
two toe failure points, which move as much between the two safeties); zones the same; the
largest bond stresses of the stages before failure within 0.1 kPa (81.6 kPa) and 6.7 times less
wall time (84 s against 560 s, line 31 against 18, same machine). At 0.1 times (line 30) the toe
collapse at 32 deg came to rest and the slope failed at 36 deg: at this resolution that collapse
is marginal (at 120 kPa it comes to rest too). Not for the random model: its top blocks' slow
collapse on their cross joints comes to rest on softer joints, and it fails at 23, 25 and 29 deg
at 1, 0.1 and 0.01 times (R 2-8 mm, lines 6, 45, 46), so keep 1 there.

The failure tilt is the first stage that fails, or with `arrest_time` > 0 the first whose failure
does not come to rest within `arrest_time` seconds (what is left of the column tops on the table,
the fastest slower than `rest_speed`; parts that fell off the table fall on into the void and are
not judged). A failure that comes to rest is not the slope's, however much of the slope fell: the
stage's log line says so (`came to rest ... tilting on`), `arrested_failures` in the summary lists
it, the discs that left the table are no longer watched, and the tilt goes on.
`first_failure_tilt_deg` is the first failing stage either way: the thesis' failure tilt, the
onset of failure ("Based on the physical test conditions at the onset of failure, the tilting
angle was set at 19 deg", thesis §5.2, of the random model). 0 (default) stops at the first
failure, as every table line before 145 ran. Measured: docs/tilting_table.md, "Failures that come
to rest". The run then goes on for `post_failure_time` so the failure surface develops, and
toppling.analysis finds it (failure points of the columns, fitted surface(s), phi), the zones,
S/H and T/H, from the displacements since the last equilibrium and the cracks.

A checkpoint is saved after every stage and every `checkpoint_every` wall seconds (a stage of
the fine packing runs for hours). Running the same command again continues from it, in the
middle of the level stage, the ramp, a stage or the post-failure run alike, as long as the
parameters are the same (except `resume`, `checkpoint_every`, `max_tilt` and
`post_failure_time`: a finished run run again with a longer one goes on after failure); `resume=0`
starts afresh, `resume=1` continues whatever checkpoint is in `out`; a checkpoint of other
parameters stops the run (it names them) rather than be overwritten.

    ./yade -x -j2 -n examples/tilting_table.py
    ./yade-batch -j1 --log='results/batch/@.log' examples/tilting_table.table examples/tilting_table.py
    ./yade-batch -j2 --lines 5,6 --log='results/batch/@.log' examples/tilting_table.table examples/tilting_table.py
                                                    # the coarse (R 2-8 mm) pair only
"""
import math

import numpy as np
from yade import O
from yade.utils import readParamsFromTable
from yade.wrapper import ParallelBondMat, SmoothJointMat

from toppling import (analysis, bonding, boundary, columns, geometry, joints, monitor, output, packing, paraview,
                      scene, tilt_report, tilt_run, tilting)

readParamsFromTable(arrangement="ideal", rmin=1e-3, rmax=4e-3, porosity=0.18, seed=1, layout_seed=1,
                    start_tilt=20.0, step=1.0, max_tilt=45.0, tilt_rate=50.0, stage_rate=10.0, damping=0.0,
                    settle_damping=0.7, chunk=0.02, rest_speed=1e-3, fail_displacement=0.05, max_stage_time=2.0,
                    fail_columns=1, post_failure_time=0.3, timestep_safety=0.5,
                    bond_tensile_strength=0.0, main_joint_friction=0.0, base_joint_friction=0.0, shrink_overlaps=1,
                    joint_stiffness_scale=1.0, bond_gap=0.0, sliding_toe=0, cut_rules=1, toe_column=1, joint_pieces=1,
                    arrest_time=0.0, resume=-1, checkpoint_every=600.0,
                    out="results/tilting_table", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

WIDTH, BLOCK_LENGTH, T, COLUMNS = 0.05, 0.10, 0.047, 15
FACE_DEG, TOP_DEG, CREST = 47.0, 27.0, 0.350  # to the table; crest height [m] (see above)
DESIGN_PLANE_DEG = 15.0  # the ideal arrangement's blocky columns have their base joints on this plane
TABLE_5_2 = {  # what differs between the two models
    "ideal": dict(young=15.05e6, knKs=1.3, bondTensileStrength=209e3),
    "random": dict(young=15.9e6, knKs=1.8, bondTensileStrength=159e3),
}
COMMON = dict(density=2900.0, frictionAngle=math.atan(0.45), bondYoung=15.9e6, bondKnKs=1.8, bondCohesion=50e3,
              bondFrictionAngle=math.radians(15), bondNormalDamping=0.2, normalDamping=0.13, thickness=T)
BOND_GAP = table.bond_gap or 1.05e-3  # Table 5-2 [m]
TABLE_5_3 = {  # main joints (kn = ks [N/m3], mu), base joints (kn = ks, mu), gap [m]
    "ideal": ((12e11, 0.17), (12e10, 0.23), 1e-4),
    "random": ((12e11, 0.15), (12e10, 0.20), 1e-4),
}
THESIS = {"ideal": dict(failure_tilt_deg=35, phi_deg=[15]), "random": dict(failure_tilt_deg=19, phi_deg=[14, 24])}

protocol = tilt_run.TiltProtocol.from_params(table)  # checks its own parameters
scene.check_safety(table.timestep_safety, "timestep_safety")  # before the out folder is made
if table.layout_seed != int(table.layout_seed) or table.layout_seed < 0:
    raise ValueError(f"layout_seed = {table.layout_seed} is invalid: it must be an integer >= 0")
SWITCHES = {"shrink_overlaps": "0 or 1", "sliding_toe": "0 or 1", "cut_rules": "0 (every block boundary a joint) or 1",
            "toe_column": "0 (no toe column) or 1", "joint_pieces": "0 (blocks by the main joints only) or 1"}
for name, valid in SWITCHES.items():
    if getattr(table, name) not in (0, 1):
        raise ValueError(f"{name} = {getattr(table, name)} is invalid: it must be {valid}")
if not 0 < table.joint_stiffness_scale <= 1:
    raise ValueError(f"joint_stiffness_scale = {table.joint_stiffness_scale} is invalid: it must be in (0, 1] "
                     "(1: Table 5-3's joint stiffnesses)")
if not 0 <= table.bond_gap <= table.rmax:
    raise ValueError(f"bond_gap = {table.bond_gap} is invalid: it must be 0 (Table 5-2's 1.05 mm) or in (0, rmax] m")
if table.arrangement not in TABLE_5_2:
    raise ValueError(f"arrangement = {table.arrangement!r} is invalid: it must be 'ideal' or 'random'")
# Calibration knobs the issue allows (0: the table's value); stay within the thesis' ranges,
# bond tensile strength 13.5-209 kPa (Tables 5-1, 5-2), joint friction 0.15-0.23 (Table 5-3).
CALIBRATION_RANGES = {"bond_tensile_strength": (13.5e3, 209e3), "main_joint_friction": (0.15, 0.23),
                      "base_joint_friction": (0.15, 0.23)}
for name, (lo, hi) in CALIBRATION_RANGES.items():
    value = getattr(table, name)
    if value and not lo <= value <= hi:
        raise ValueError(f"{name} = {value} is invalid: it must be 0 (the thesis' table) or in its range [{lo:g}, {hi:g}]")
if table.bond_tensile_strength:
    TABLE_5_2[table.arrangement]["bondTensileStrength"] = table.bond_tensile_strength
main_joints, base_joints, gap = TABLE_5_3[table.arrangement]
scale = table.joint_stiffness_scale
TABLE_5_3[table.arrangement] = ((scale * main_joints[0], table.main_joint_friction or main_joints[1]),
                                (scale * base_joints[0], table.base_joint_friction or base_joints[1]), gap)
criteria = tilting.StageCriteria(table.chunk, table.rest_speed, table.fail_displacement, table.max_stage_time,
                                 table.fail_columns)


def profile(d: float) -> float:
    """Height of the outline at distance d from the toe."""
    crest_distance = CREST / math.tan(math.radians(FACE_DEG))
    if d <= crest_distance:
        return d * math.tan(math.radians(FACE_DEG))
    return CREST - (d - crest_distance) * math.tan(math.radians(TOP_DEG))


def cross_joint_heights(layout: columns.ColumnLayout) -> dict[int, list[float]]:
    """Where the cross joints cut each column (before the layout's rules drop the unsupported)."""
    if table.arrangement == "ideal":  # one base joint per blocky column, on the design plane
        plane = math.tan(math.radians(DESIGN_PLANE_DEG))
        return {k: [plane * (k - 0.5) * WIDTH] for k in range(1, layout.count + 1, 2)}
    phases = np.random.default_rng(table.layout_seed).uniform(0, BLOCK_LENGTH, layout.count)
    return {k: layout.stacked_blocks(k, BLOCK_LENGTH, phases[k - 1]) for k in range(1, layout.count + 1)}


def bonded_rock(discs: list[tuple[float, float, float]], table_surface: tuple) -> list[int]:
    """The discs (x, y, r) as the model's rock in a scene with its engines: discs without a bond
    partner dropped, those within Rmax of ``table_surface`` (a segment) fixed, all bonded."""
    ids = scene.add_discs(discs, ParallelBondMat(**COMMON, **TABLE_5_2[table.arrangement]))
    O.engines = scene.engines(gravity=(0, -tilting.G, 0), local_damping=table.damping, safety=table.timestep_safety)
    floaters = set(bonding.remove_floaters(BOND_GAP, ids=ids))
    ids = [i for i in ids if i not in floaters]
    boundary.fix(boundary.near([table_surface], table.rmax, ids), "xy")
    # Bond at once: the packer leaves the discs relaxed (mean overlap < 0.2 % Rmin), and without
    # its walls loose discs would slump off the steps (the thesis settles inside walls, §5.3.2).
    bonding.bond_within_gap(BOND_GAP, ids)
    return ids


def column_layout() -> columns.ColumnLayout:
    return columns.ColumnLayout.under_profile(COLUMNS * WIDTH, WIDTH, COLUMNS, profile)


def build() -> columns.ColumnLayout:
    layout = column_layout()
    discs = packing.pack_polygon(geometry.region(layout.section()), table.rmin, table.rmax, table.porosity,
                                 seed=table.seed).discs
    if table.shrink_overlaps:
        discs = packing.shrink_overlaps(discs)
    if not table.toe_column:  # the slope as the R 2-8 mm packing leaves it: no bonded disc in A-1
        discs = [d for d in discs if layout.column_of(d[0]) != 1]
    bonded_rock(discs, ((0, 0), (layout.toe_x, 0)))
    (kn_main, mu_main), (kn_base, mu_base), gap = TABLE_5_3[table.arrangement]
    main = SmoothJointMat(normalStiffness=kn_main, shearStiffness=kn_main,
                          frictionAngle=math.atan(mu_main), gap=gap, thickness=T)
    base = SmoothJointMat(normalStiffness=kn_base, shearStiffness=kn_base,
                          frictionAngle=math.atan(mu_base), gap=gap, thickness=T)
    cuts = cross_joint_heights(layout)
    cross = layout.cross_joints(cuts, BLOCK_LENGTH, sliding_toe=bool(table.sliding_toe),
                                every_cut=not table.cut_rules)
    rules = " by the layout's rules" if table.cut_rules else " (cut_rules 0)"
    print(f"cross joints: {len(cross.segmentStarts)} of {sum(map(len, cuts.values()))} cuts kept{rules}", flush=True)
    joints.install_joints([(layout.main_joints(), main), (cross, base)],
                          lo=(-1, -1), hi=(layout.toe_x + 1, 1), pieces=bool(table.joint_pieces))
    return layout


def column_members(layout: columns.ColumnLayout) -> dict[int, list]:
    """The discs of each column (1-based)."""
    members = {k: [] for k in range(1, layout.count + 1)}
    for b in O.bodies:
        k = layout.column_of(b.state.pos[0]) if b is not None else 0
        if k:
            members[k].append(b)
    return members


def column_top_bands(members: dict[int, list], depth: float) -> dict[str, list[int]]:
    """The rock discs (>= 2 intact bonds) within ``depth`` of each column's top, by column
    label: their centroid is what the stage criteria watch (a loose disc rolling off is not the
    column moving). A column too small for the discs to bond (the toe column at R 2-8 mm) is not
    watched."""
    bands = {}
    for k, discs in members.items():
        rock = bonding.rock([b.id for b in discs])
        if not rock:
            print(f"column {analysis.column_label(k)}: no bonded discs (rmax = {table.rmax} m), not watched")
            continue
        top = max(O.bodies[i].state.pos[1] for i in rock)
        bands[analysis.column_label(k)] = [i for i in rock if O.bodies[i].state.pos[1] > top - depth]
    return bands


# ---- build or resume ----
inputs = output.table_inputs(table)
checkpoint = monitor.Checkpoint(table.out)
# parameters newer than some checkpoints: the value those runs had
ADDED = {"shrink_overlaps": 0, "joint_stiffness_scale": 1.0, "fail_columns": 1, "bond_gap": 0.0, "settle_damping": 0.7,
         "stage_rate": 0.0, "layout_seed": 1, "sliding_toe": 0, "cut_rules": 1, "toe_column": 1, "joint_pieces": 0,
         "arrest_time": 0.0}
if checkpoint.continues(inputs, table.resume, free=tilt_run.FREE, added=ADDED):
    state = checkpoint.load()
    print(f"resuming {table.out} in its {state['phase']['name']} phase at {state['tilt']} deg "
          "(resume=0 starts afresh)", flush=True)
    state["inputs"] = inputs  # the run goes on with these (resume=1 may change any): the same command continues it
    layout = columns.ColumnLayout(**state["layout"])
    points = monitor.MonitoringPoints.from_dict(state["points"])
else:
    output.discard_summary(table.out)
    layout = build()
    ids = [b.id for b in O.bodies if b is not None]
    points = monitor.column_top_points(layout, bonding.rock(ids))  # a loose top disc may drop off the table
    state = tilt_run.fresh_state(inputs, layout, ids, column_top_bands(column_members(layout), 2 * table.rmax),
                                 table.start_tilt)
series = paraview.ParaViewSeries(f"{table.out}/paraview", joints.rock_functor().joints.blockOfBody, state.get("series"))
run = tilt_run.TiltRun(protocol, criteria, checkpoint, state, layout, points, series, table.rmin, table.rmax)
run.run()
tilt_report.report(run, table.out, THESIS[table.arrangement], table.arrangement)
