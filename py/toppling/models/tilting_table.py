"""The tilting-table model (thesis §5.2): columns of blocks standing on a table, bonded discs
cut by main joints between the columns and cross joints inside them, tilted by turning gravity
until they topple.

Table frame: the table surface is y = 0, the columns stand along +y, column 1 (the toe) is at
the right. The reconstruction of the thesis' figures (outline, base joints on a design plane,
the random arrangement's cut rules) and why: docs/cases/tilting_table.md. Every number of the
thesis' cases comes from the caller (examples/params.py).
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass
from typing import Any, Optional

import numpy as np
from yade import O
from yade.wrapper import ParallelBondMat, SmoothJointMat

from toppling.analyse import failure
from toppling.build import bonding, boundary, columns, engines, geometry, jcfpm, joints, packing
from toppling.build.discs import add_discs
from toppling.io import output, paraview
from toppling.load import tilting
from toppling.run import tilt_run
from toppling.run.checkpoint import Checkpoint
from toppling.run.monitoring import MonitoringPoints, column_top_points

ARRANGEMENTS = ("ideal", "random")
# What a run writes per disc, twice over (a checkpoint is written aside before it replaces the
# last): measured, 16 MB for the 5,955 discs of the ideal model at R 1-4 mm.
OUTPUT_BYTES_PER_DISC = 2 * 2.7e3


def check_arrangement(arrangement: str) -> None:
    if arrangement not in ARRANGEMENTS:
        raise ValueError(f"arrangement = {arrangement!r} is invalid: it must be 'ideal' or 'random'")


@dataclass
class Outline:
    """``columns`` columns ``width`` [m] wide whose flat tops meet a profile rising from the toe
    at ``face_deg`` to the table up to ``crest`` [m], then falling into the slope at ``top_deg``."""
    width: float
    columns: int
    face_deg: float
    top_deg: float
    crest: float

    def profile(self, d: float) -> float:
        """Height of the outline at distance ``d`` from the toe."""
        crest_distance = self.crest / math.tan(math.radians(self.face_deg))
        if d <= crest_distance:
            return d * math.tan(math.radians(self.face_deg))
        return self.crest - (d - crest_distance) * math.tan(math.radians(self.top_deg))

    def layout(self) -> columns.ColumnLayout:
        return columns.ColumnLayout.under_profile(self.columns * self.width, self.width, self.columns, self.profile)


@dataclass
class JointMaterial:
    stiffness: float  # kn [N/m3]
    friction: float  # mu
    shear_stiffness: float | None = None  # ks [N/m3]; None: = kn

    def material(self, gap: float, thickness: float) -> SmoothJointMat:
        shear = self.stiffness if self.shear_stiffness is None else self.shear_stiffness
        return SmoothJointMat(normalStiffness=self.stiffness, shearStiffness=shear,
                              frictionAngle=math.atan(self.friction), gap=gap, thickness=thickness)


@dataclass
class BondedDiscs:
    """What a model's rock is made of: discs R ``rmin``-``rmax`` [m] packed at ``porosity`` with
    ``seed``, bonded within ``bond_gap`` [m], cut by joints installed with ``joint_gap`` [m]."""
    joint_gap: float
    bond_gap: float
    rmin: float
    rmax: float
    porosity: float
    seed: int

    def __post_init__(self):
        if not 0 < self.bond_gap <= self.rmax:
            raise ValueError(f"bond_gap = {self.bond_gap} is invalid: it must be in (0, rmax] m")


@dataclass
class TiltingTable(BondedDiscs):
    """The model: ``outline``, ``rock`` (ParallelBondMat's keyword arguments, ``thickness``
    included), bonds between discs within ``bond_gap`` [m], joints of ``main`` and ``base``
    material with ``joint_gap`` [m]; discs R ``rmin``-``rmax`` [m] packed at ``porosity`` with
    ``seed``. ``arrangement`` 'ideal': one base joint in every other column from the toe, on a
    plane rising from the toe at ``design_plane_deg``; 'random': blocks ``block_length`` [m]
    long stacked in every column at a random offset (``layout_seed``), cut where the layout's
    rules keep a cut (``cut_rules``; False: at every block boundary). ``joint_pieces``: contacts
    made after the joints are installed are joints between pieces of rock. ``z_order``: discs
    numbered along a Z-order curve (a faster step, other rounding). ``face_closure``: joint
    contacts made later start with their faces' closure (``joints.install_joints``)."""
    outline: Outline
    rock: dict[str, Any]
    main: JointMaterial
    base: JointMaterial
    arrangement: str
    block_length: float
    design_plane_deg: float
    layout_seed: int = 1
    cut_rules: bool = True
    joint_pieces: bool = True
    z_order: bool = False
    timestep_safety: float = 0.5
    damping: float = 0.0
    face_closure: bool = False

    def __post_init__(self):
        super().__post_init__()
        check_arrangement(self.arrangement)
        if self.layout_seed != int(self.layout_seed) or self.layout_seed < 0:
            raise ValueError(f"layout_seed = {self.layout_seed} is invalid: it must be an integer >= 0")
        engines.check_safety(self.timestep_safety, "timestep_safety")

    def cross_joint_heights(self, layout: columns.ColumnLayout) -> dict[int, list[float]]:
        """Where the cross joints cut each column (before the layout's rules drop the unsupported)."""
        if self.arrangement == "ideal":
            plane = math.tan(math.radians(self.design_plane_deg))
            return {k: [plane * (k - 0.5) * layout.width] for k in range(1, layout.count + 1, 2)}
        phases = np.random.default_rng(self.layout_seed).uniform(0, self.block_length, layout.count)
        return {k: layout.stacked_blocks(k, self.block_length, phases[k - 1]) for k in range(1, layout.count + 1)}

    def bonded_rock(self, discs: list[tuple[float, float, float]], table_surface: tuple) -> list[int]:
        """The discs (x, y, r) as the model's rock (``bonded_rock``), held near ``table_surface``."""
        return bonded_rock(discs, self.rock, self.bond_gap, [table_surface], self.rmax, self.damping,
                           self.timestep_safety)

    def pack(self, layout: columns.ColumnLayout) -> list[tuple[float, float, float]]:
        return packed_discs(layout.section(), self.rmin, self.rmax, self.porosity, self.seed, self.z_order)

    def expected_discs(self) -> int:
        outline = geometry.region(self.outline.layout().section())
        return packing.disc_count(outline.area(), self.rmin, self.rmax, self.porosity)

    def build(self) -> columns.ColumnLayout:
        """The bonded, jointed columns in an empty scene; returns their layout."""
        layout = self.outline.layout()
        self.bonded_rock(self.pack(layout), ((0, 0), (layout.toe_x, 0)))
        cuts = self.cross_joint_heights(layout)
        cross = layout.cross_joints(cuts, self.block_length, every_cut=not self.cut_rules)
        print(f"cross joints: {len(cross.segmentStarts)} of {sum(map(len, cuts.values()))} cuts kept", flush=True)
        t = self.rock["thickness"]
        joints.install_joints([(layout.main_joints(), self.main.material(self.joint_gap, t)),
                               (cross, self.base.material(self.joint_gap, t))],
                              lo=(-1, -1), hi=(layout.toe_x + 1, 1), pieces=self.joint_pieces,
                              face_closure=self.face_closure)
        return layout

    def column_top_bands(self, layout: columns.ColumnLayout) -> dict[str, list[int]]:
        return column_top_bands(layout, self.rmax)


def packed_discs(section: list[tuple[float, float]], rmin: float, rmax: float, porosity: float, seed: int,
                 z_order: bool) -> list[tuple[float, float, float]]:
    """The discs filling ``section`` (a kept packing), overlaps shrunk (a stress-free bond would
    otherwise hold the packing's overlap force in tension from the first step), in Z-order if asked."""
    discs = packing.pack_polygon(geometry.region(section), rmin, rmax, porosity, seed=seed, keep=True).discs
    discs = packing.shrink_overlaps(discs)
    return packing.z_order(discs) if z_order else discs


def bonded_rock(discs: list[tuple[float, float, float]], rock: dict[str, Any], bond_gap: float,
                held: list[tuple], rmax: float, damping: float, safety: float) -> list[int]:
    """The discs (x, y, r) as rock of ParallelBondMat(**``rock``) in a scene with its engines: discs
    without a bond partner within ``bond_gap`` dropped, those within ``rmax`` of the ``held``
    segments fixed, all bonded."""
    ids = bond_in_scene(add_discs(discs, ParallelBondMat(**rock)), bond_gap, damping, safety)
    boundary.fix(boundary.near(held, rmax, ids), "xy")
    return ids


def bond_in_scene(ids: list[int], bond_gap: float, damping: float, safety: float) -> list[int]:
    """Give the scene its engines, drop the discs (of ``ids``) without a bond partner within
    ``bond_gap`` and bond the rest; returns the discs kept."""
    O.engines = engines.engines(gravity=(0, -engines.G, 0), local_damping=damping, safety=safety)
    floaters = set(bonding.remove_floaters(bond_gap, ids=ids))
    ids = [i for i in ids if i not in floaters]
    # Bond at once: the packer leaves the discs relaxed, and without its walls loose discs
    # would slump off the steps (the thesis settles inside walls, §5.3.2).
    bonding.bond_within_gap(bond_gap, ids)
    return ids


def column_top_bands(layout: columns.ColumnLayout, rmax: float) -> dict[str, list[int]]:
    """The rock discs (>= 2 intact bonds) within 2 ``rmax`` of each column's top, by column
    label: their median position is what the stage criteria watch (a loose disc rolling off, or
    a corner breaking off, is not the column moving). A column too small for the discs to bond
    is not watched."""
    members = {k: [] for k in range(1, layout.count + 1)}
    for b in O.bodies:
        k = layout.column_of(b.state.pos[0]) if b is not None and b.state.pos[1] > 0 else 0
        if k:
            members[k].append(b.id)
    bands = {}
    for k, ids in members.items():
        rock = bonding.rock(ids)
        if not rock:
            print(f"column {failure.column_label(k)}: no bonded discs (rmax = {rmax} m), not watched")
            continue
        top = max(O.bodies[i].state.pos[1] for i in rock)
        bands[failure.column_label(k)] = [i for i in rock if O.bodies[i].state.pos[1] > top - 2 * rmax]
    return bands


def check_switch(params: Any, name: str) -> bool:
    value = getattr(params, name)
    if value not in (0, 1):
        raise ValueError(f"{name} = {value} is invalid: it must be 0 or 1")
    return bool(value)


def from_params(p: Any, thesis: Any) -> TiltingTable:
    """The model from a parameter set ``p`` (``yade.params.table``; the names of
    examples/params.py's TILTING_TABLE_IDEAL) and the thesis' tables ``thesis`` (the module
    examples/params.py: TABLE_5_2, TABLE_5_3, the outline ...). A thesis value given as 0 is
    the table's; calibrated values must lie in the thesis' ranges (CALIBRATION_RANGES)."""
    check_arrangement(p.arrangement)
    for name, (lo, hi) in thesis.CALIBRATION_RANGES.items():
        if getattr(p, name) and not lo <= getattr(p, name) <= hi:
            raise ValueError(f"{name} = {getattr(p, name)} is invalid: it must be 0 (the thesis' table) or in "
                             f"its range [{lo:g}, {hi:g}]")
    if not 0 < p.joint_stiffness_scale <= 1:
        raise ValueError(f"joint_stiffness_scale = {p.joint_stiffness_scale} is invalid: it must be in (0, 1] "
                         "(1: Table 5-3's joint stiffnesses)")
    rock, joint = thesis.TABLE_5_2[p.arrangement], thesis.TABLE_5_3[p.arrangement]
    main, base = joint["main"], joint["base"]
    return TiltingTable(
        outline=Outline(**thesis.TILTING_TABLE_OUTLINE),
        rock={**thesis.TABLE_5_2_COMMON, **rock, "bondTensileStrength": p.bond_tensile_strength or rock["bondTensileStrength"]},
        main=JointMaterial(p.joint_stiffness_scale * main[0], p.main_joint_friction or main[1]),
        base=JointMaterial(p.joint_stiffness_scale * base[0], p.base_joint_friction or base[1]),
        joint_gap=joint["gap"], bond_gap=p.bond_gap or thesis.TABLE_5_2_BOND_GAP, arrangement=p.arrangement,
        block_length=thesis.BLOCK_LENGTH, design_plane_deg=thesis.DESIGN_PLANE_DEG, rmin=p.rmin, rmax=p.rmax,
        porosity=p.porosity, seed=p.seed, layout_seed=p.layout_seed, cut_rules=check_switch(p, "cut_rules"),
        joint_pieces=check_switch(p, "joint_pieces"), z_order=check_switch(p, "z_order"),
        timestep_safety=p.timestep_safety, damping=p.damping, face_closure=check_switch(p, "face_closure"))


def built(model, laws: str, inputs: dict, protocol: tilt_run.TiltProtocol) -> dict[str, Any]:
    """The state of a run on ``model`` built afresh."""
    layout = model.build()
    if not hasattr(model, "settled"):  # jointed as built
        jcfpm.use(laws, cracks=True)
    ids = [b.id for b in O.bodies if b is not None]
    points = column_top_points(layout, bonding.rock(ids))  # a loose top disc may drop off the table
    state = tilt_run.fresh_state(inputs, layout, ids, model.column_top_bands(layout), protocol.start_tilt)
    return {**state, "points": points.as_dict()}


def settled_rock(store: Checkpoint) -> dict[str, Any]:
    """The state of a run starting from the settled scene another run of the same rock left in ``store``."""
    state = store.load()
    state["settled_from"] = os.path.dirname(store.scene_path)
    print(f"the settled rock from {state['settled_from']} (its settling took {state['wall_time']:.0f} s)", flush=True)
    return state


def start(model, protocol: tilt_run.TiltProtocol, criteria: tilting.StageCriteria, inputs: dict,
          out: str, resume: int, laws: str = "ours", store: Optional[Checkpoint] = None) -> tilt_run.TiltRun:
    """The run of ``model`` (a TiltingTable, or any model with its ``build``, ``expected_discs``,
    ``column_top_bands``, ``rmin`` and ``rmax``; with a ``settled()`` method, called once the
    model stands at the protocol's settle_tilt) in ``out`` with ``inputs`` (the parameters it was
    made from): continued from the checkpoint there (``resume``: Checkpoint.continues), else
    from the settled scene in ``store`` (tilt_run.settled_store) if a run of the same rock left
    one, else built afresh. ``laws`` 'jcfpm' hands the scene to YADE's JCFpm once it is jointed
    (``toppling.build.jcfpm``)."""
    jcfpm.check_model(laws)
    output.prepare_out(out, OUTPUT_BYTES_PER_DISC * model.expected_discs())
    checkpoint = Checkpoint(out)
    if checkpoint.continues(inputs, resume, free=tilt_run.FREE):
        state = checkpoint.load()
        print(f"resuming {out} in its {state['phase']['name']} phase at {state['tilt']} deg "
              "(resume=0 starts afresh)", flush=True)
    else:
        output.discard_summary(out)
        state = settled_rock(store) if store is not None and store.exists() else built(model, laws, inputs, protocol)
    state["inputs"] = inputs  # the run goes on with these (resume=1 may change any): the same command continues it
    points = MonitoringPoints.from_dict(state["points"])
    series = paraview.ParaViewSeries(f"{out}/paraview", joints.blocks(), state.get("series"))
    settled = getattr(model, "settled", None)

    def joints_known() -> None:  # the pictures colour the blocks the joints made
        settled()
        series.block_of_body = joints.blocks()
        jcfpm.use(laws, cracks=True)

    return tilt_run.TiltRun(protocol, criteria, checkpoint, state, points, series, model.rmin, model.rmax,
                            settled=joints_known if settled else None, store=store)
