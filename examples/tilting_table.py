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
* `z_order` = 1 (default) numbers the discs along a Z-order curve, so that neighbours get near ids
  and a step reads bodies near in memory: the R 1-2.5 mm packing's step runs 1.3 times faster,
  the R 2-8 mm one's, which fits the cache either way, 1.1 times (README, "Cost of a
  tilting-table run"). The discs are the same; the order in which forces are summed changes, and
  with it a run's rounding. The table's rows run before it keep 0, so they reproduce.

Calibration (the issue allows joint friction and bond strengths within the thesis' ranges;
`bond_tensile_strength`, `main_joint_friction`, `base_joint_friction`, 0 = the tables' value).
The ideal model's current rows use 95 kPa (at Table 5-2's 209 kPa no bond of the reconstructed
slope breaks up to 44 deg, R 1-4 mm; at 95 kPa sixty-five R 1-2.5 mm packing seeds fail
at 35.4 deg on average, seventy-six R 1-4 mm seeds at 36.4 deg), the random model's 65 kPa
(Table 5-2's 159 kPa scaled as the ideal model's 85/209, the scale of its calibration before 95 kPa,
which meets 19 deg on average over sixteen draws). Without local damping the
slope fails in the stage in which its most stressed bond reaches the strength, so the packing seed
moves the failure tilt as much as the strength does (docs/tilting_table.md: "Ideal model:
bond-strength calibration", "Without local damping", "The random model at R 1-4 mm between
pieces").

Loading: the discs within Rmax of the table are fixed in x and y (§5.2.4.2); gravity is turned
by the tilt (Fig 5-7). The model first comes to rest on the level table, then the tilt rises
steadily at `tilt_rate` deg/s to `start_tilt` (a tilt switched on at once loads the columns
dynamically, up to twice their static stress; `start_tilt` 0 skips it), then by `step` degrees
per stage, each step at once or, with `stage_rate` > 0, at that many deg/s. If the ramp cracks
the rock (not counting bonds that held a loose disc), a warning names the tilt of its first crack:
a rerun with `start_tilt` below it judges those tilts in stages. Each stage runs in chunks of
`chunk` seconds until

* equilibrium: the fastest column top (the median position of the bonded discs within 2 Rmax
  of the top: a loose disc rattling, or a corner that breaks off, is not a column moving)
  moves slower than `rest_speed`, or
* failure: a column top still moves faster than `rest_speed` after `max_stage_time` and has
  moved further than `rest_speed` times the stage's time (less is a column ringing in place), or
  `fail_columns` column tops have moved more than `fail_displacement` (one column width: toppled
  off their neighbours). With `fail_columns` 2 a column that topples off alone (the toe column
  A-1 once its root has cracked) is gone, watched no more, and the others decide (all of them,
  once fewer than `fail_columns` are left). A local
  collapse that comes to rest is not failure. Why these thresholds: README, "Failure tilt".

Damping: the thesis' only damping is viscous, in the contacts and bonds (Table 5-2's critical
damping ratios 0.13 and 0.2, always on). `damping` adds NewtonIntegrator's local damping while
the table tilts (0 by default, as in the thesis; it also brakes a collapse), `settle_damping`
while the model comes to rest on the level table (docs/tilting_table.md, "Local damping").

Time step: GlobalStiffnessTimeStepper's, dt = sqrt(2) `timestep_safety` min sqrt(m/K), updated
every 100 steps. `joint_stiffness_scale` multiplies Table 5-3's joint stiffnesses, which set the
time step; 0.01 leaves the ideal model's failure as it is and takes 6.7 times less wall time,
but not the random model's (docs/tilting_table.md, "Time step", "Joint stiffness").

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
toppling.analyse.failure finds it (failure points of the columns, fitted surface(s), phi, and the overall
surface's phi, one line through all the points), the zones,
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
    ./yade-batch -j2 --lines 204,197,155 --log='results/batch/@.log' examples/tilting_table.table examples/tilting_table.py
                                                    # the thesis' cases at their current settings (README)
"""
import math

import numpy as np
from yade import O
from yade.utils import readParamsFromTable
from yade.wrapper import ParallelBondMat, SmoothJointMat

from toppling.analyse import failure
from toppling.build import bonding, boundary, columns, engines, geometry, joints, packing
from toppling.build.discs import add_discs
from toppling.io import output, paraview, tilt_report
from toppling.load import tilting
from toppling.run import tilt_run
from toppling.run.monitoring import MonitoringPoints, column_top_points
from toppling.run.checkpoint import Checkpoint

readParamsFromTable(arrangement="ideal", rmin=1e-3, rmax=4e-3, porosity=0.18, seed=1, layout_seed=1,
                    start_tilt=20.0, step=1.0, max_tilt=45.0, tilt_rate=50.0, stage_rate=10.0, damping=0.0,
                    settle_damping=0.7, chunk=0.02, rest_speed=1e-3, fail_displacement=0.05, max_stage_time=2.0,
                    fail_columns=1, post_failure_time=0.3, timestep_safety=0.5,
                    bond_tensile_strength=0.0, main_joint_friction=0.0, base_joint_friction=0.0, shrink_overlaps=1,
                    joint_stiffness_scale=1.0, bond_gap=0.0, sliding_toe=0, cut_rules=1, toe_column=1, joint_pieces=1,
                    arrest_time=0.0, z_order=1, resume=-1, checkpoint_every=600.0,
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
engines.check_safety(table.timestep_safety, "timestep_safety")  # before the out folder is made
if table.layout_seed != int(table.layout_seed) or table.layout_seed < 0:
    raise ValueError(f"layout_seed = {table.layout_seed} is invalid: it must be an integer >= 0")
SWITCHES = {"shrink_overlaps": "0 or 1", "sliding_toe": "0 or 1", "cut_rules": "0 (every block boundary a joint) or 1",
            "toe_column": "0 (no toe column) or 1", "joint_pieces": "0 (blocks by the main joints only) or 1",
            "z_order": "0 (the packer's order) or 1 (discs near in space get near ids: a faster step)"}
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
    ids = add_discs(discs, ParallelBondMat(**COMMON, **TABLE_5_2[table.arrangement]))
    O.engines = engines.engines(gravity=(0, -tilting.G, 0), local_damping=table.damping, safety=table.timestep_safety)
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
    if table.z_order:
        discs = packing.z_order(discs)
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
    label: their median position is what the stage criteria watch (a loose disc rolling off, or
    a corner breaking off, is not the column moving). A column too small for the discs to bond
    (the toe column at R 2-8 mm) is not watched."""
    bands = {}
    for k, discs in members.items():
        rock = bonding.rock([b.id for b in discs])
        if not rock:
            print(f"column {failure.column_label(k)}: no bonded discs (rmax = {table.rmax} m), not watched")
            continue
        top = max(O.bodies[i].state.pos[1] for i in rock)
        bands[failure.column_label(k)] = [i for i in rock if O.bodies[i].state.pos[1] > top - depth]
    return bands


# ---- build or resume ----
inputs = output.table_inputs(table)
checkpoint = Checkpoint(table.out)
# parameters newer than some checkpoints: the value those runs had
ADDED = {"shrink_overlaps": 0, "joint_stiffness_scale": 1.0, "fail_columns": 1, "bond_gap": 0.0, "settle_damping": 0.7,
         "stage_rate": 0.0, "layout_seed": 1, "sliding_toe": 0, "cut_rules": 1, "toe_column": 1, "joint_pieces": 0,
         "arrest_time": 0.0, "z_order": 0}
if checkpoint.continues(inputs, table.resume, free=tilt_run.FREE, added=ADDED):
    state = checkpoint.load()
    print(f"resuming {table.out} in its {state['phase']['name']} phase at {state['tilt']} deg "
          "(resume=0 starts afresh)", flush=True)
    state["inputs"] = inputs  # the run goes on with these (resume=1 may change any): the same command continues it
    points = MonitoringPoints.from_dict(state["points"])
else:
    output.discard_summary(table.out)
    layout = build()
    ids = [b.id for b in O.bodies if b is not None]
    points = column_top_points(layout, bonding.rock(ids))  # a loose top disc may drop off the table
    state = tilt_run.fresh_state(inputs, layout, ids, column_top_bands(column_members(layout), 2 * table.rmax),
                                 table.start_tilt)
series = paraview.ParaViewSeries(f"{table.out}/paraview", joints.rock_functor().joints.blockOfBody, state.get("series"))
run = tilt_run.TiltRun(protocol, criteria, checkpoint, state, points, series, table.rmin, table.rmax)
run.run()
tilt_report.report(run, table.out, THESIS[table.arrangement], table.arrangement)
