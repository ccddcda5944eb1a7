"""The equivalent slope (thesis §5.3): the tilting table's ideal arrangement turned by its failure
tilt into a slope under gravity, on a foundation of rock.

Built in the table frame of ``toppling.models.tilting_table`` (columns upright on y = 0, column 1
at the toe, the largest x; gravity turned by ``tilt_deg``), so that the columns, the stage
criteria and the failure analysis are the tilting table's. The thesis' geometry is in its
figures only (Figs 5-16 … 5-18, 5-20); our reconstruction from its text and tables:

* **Slope.** Turning the table by its failure tilt α = 35° makes the main joints dip
  δ = 90° − α = 55° into the slope. A face at θ = 98° rises at 180° − θ − α = 47° to the table,
  a top surface at β = 8° falls at α − β = 27° from the crest; the crest stands H = 0.475 m
  above the toe. Columns ``spacing`` wide (0.047 m) have flat tops at the outline's height at
  their centres, as the experiment's blocks (§5.3.1: "both the configuration and the dimensions
  of the blocks remain the same"); they run until the top surface meets the table plane, 22
  columns at 0.047 m ("negligible deformation in columns 14 to 22").
* **Foundation.** The table becomes rock: below the table plane, down to a horizontal base
  through the toe, up to a vertical right side where the last column ends (the thesis fixes
  "the right side ... in x and the base in x and y"; in the table frame both are held in x and y,
  the right side lying in the no-movement zone). No main joint enters it.
* **Base joints**, one per blocky column (every other column from the toe), on a plane rising
  from the toe at ``base_plane_deg`` to the table plane, so that a blocky column rests on a
  joint and a flexural one is bonded through ("its lack of joint base", §5.3.2). The base model
  puts it at the tilting table's design plane (15°): the thesis' equivalent slope is its ideal
  model turned by 35°. Table 5-7's D/H (the horizontal distance from the toe to the centre of a
  merged pair (N2-N1), over H) would rather put it on the table plane (D/H = N1 · spacing · cos α
  / H = 0.0811 N1, within 0.02 of the table's sixteen values; 0.066 N1 on the 15° plane), but
  there the slope stands or slides on that plane at every strength and friction the thesis
  allows (docs/cases/equivalent_slope.md), where the thesis' topples above a surface at 15°.

A base joint is a ``BaseJoint``: the columns it crosses and its height above the table plane,
so that merged joints, one continuous joint and a second set are data.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Sequence

from yade.wrapper import JointSetGeometry

from toppling.build import columns, engines, geometry, joints, packing
from toppling.checks import require
from toppling.models.tilting_table import (BondedDiscs, JointMaterial, Outline, bonded_rock, column_top_bands,
                                           packed_discs)
from toppling.run import tilt_run


@dataclass(frozen=True)
class BaseJoint:
    """A joint across columns ``first`` to ``last`` (1-based from the toe), ``height`` [m] above
    the table plane, measured along the main joints."""
    first: int
    last: int
    height: float = 0.0


def every_other_column(layout: columns.ColumnLayout, plane_deg: float = 0.0) -> list[BaseJoint]:
    """The base model's base joints: one in every other column from the toe (1, 3, 5, ...), where
    a plane rising from the toe at ``plane_deg`` to the table plane crosses the column's centre,
    in the columns it crosses below their tops."""
    rise = math.tan(math.radians(plane_deg))
    found = [BaseJoint(k, k, rise * (k - 0.5) * layout.width) for k in range(1, layout.count + 1, 2)]
    return [j for j in found if j.height < layout.heights[j.first - 1]]


def merged(joints_: Sequence[BaseJoint], n1: int, height: float = 0.0) -> list[BaseJoint]:
    """Table 5-7's case (N2-N1), N2 = n1 + 1: the lowest single-column base joint of columns n1
    and n1 + 1 replaced by one joint crossing both at ``height`` (one of the two is a flexural
    column, which had none)."""
    pair = (n1, n1 + 1)
    single = [j for j in joints_ if j.first == j.last and j.first in pair]
    dropped = min(single, key=lambda j: j.height) if single else None
    kept = [j for j in joints_ if j is not dropped]
    return sorted(kept + [BaseJoint(n1, n1 + 1, height)], key=lambda j: (j.height, j.first))


@dataclass(frozen=True)
class SlopeShape:
    """The slope of thesis §5.3.1: height ``height`` [m] at the crest, main joints dipping
    ``joint_dip_deg`` into it, face at ``face_deg`` and top surface at ``top_deg`` to the
    horizontal (θ and β), columns ``spacing`` [m] wide; ``columns`` of them from the toe (0: all
    that stand above the table plane, up to where the top surface meets it)."""
    height: float
    joint_dip_deg: float
    face_deg: float
    top_deg: float
    spacing: float
    columns: int = 0

    def __post_init__(self):
        require("height", self.height, "(0, inf)")
        require("joint_dip_deg", self.joint_dip_deg, "(0, 90)")
        require("top_deg", self.top_deg, f"[0, {90 - self.joint_dip_deg:g})")  # the top must fall towards the table
        # the face must rise from the table plane and lean no further out than the main joints
        require("face_deg", self.face_deg, f"({self.joint_dip_deg:g}, {90 + self.joint_dip_deg:g})")
        require("spacing", self.spacing, "(0, inf)")
        require("columns", self.columns, "whole [0, inf)")

    @property
    def tilt_deg(self) -> float:
        """The table's tilt that makes the slope: the main joints' dip from the vertical."""
        return 90.0 - self.joint_dip_deg

    def outline(self) -> Outline:
        """The columns' outline in the table frame, as many columns as stand above the table."""
        a = math.radians(self.tilt_deg)
        face = 180.0 - self.face_deg - self.tilt_deg
        top = self.tilt_deg - self.top_deg
        crest = self.height / (math.sin(a) / math.tan(math.radians(face)) + math.cos(a))
        reach = crest / math.tan(math.radians(face)) + crest / math.tan(math.radians(top))
        count = int(reach / self.spacing + 0.5)
        if self.columns > count:
            raise ValueError(f"columns = {self.columns} is invalid: the slope has {count} columns above the table plane")
        return Outline(width=self.spacing, columns=self.columns or count, face_deg=face, top_deg=top, crest=crest)


@dataclass
class EquivalentSlope(BondedDiscs):
    """The model: ``shape``, ``rock`` (ParallelBondMat's keyword arguments, ``thickness``
    included), bonds between discs within ``bond_gap`` [m], main joints of ``main`` and base
    joints (``base_joints``; None: every other column, on a plane rising from the toe at
    ``base_plane_deg`` to the table plane) of ``base`` material with ``joint_gap`` [m];
    ``merged_pair`` N1 > 0 merges Table 5-7's pair (N1 + 1)-N1; discs R ``rmin``-``rmax`` [m]
    packed at ``porosity`` with ``seed``. With
    ``joints_into_foundation`` the main joints run on down to the horizontal base (the other
    reading of the thesis' foundation: the flexural columns rooted at the held base, not at the
    table plane)."""
    shape: SlopeShape
    rock: dict[str, Any]
    main: JointMaterial
    base: JointMaterial
    base_joints: list[BaseJoint] | None = None
    base_plane_deg: float = 0.0
    merged_pair: int = 0
    joints_into_foundation: bool = False
    z_order: bool = False
    timestep_safety: float = 0.5
    damping: float = 0.0
    face_closure: bool = False
    layout: columns.ColumnLayout = field(init=False)

    def __post_init__(self):
        super().__post_init__()
        engines.check_safety(self.timestep_safety, "timestep_safety")
        self.layout = self.shape.outline().layout()
        require("base_plane_deg", self.base_plane_deg, "[0, 90)")
        if self.base_joints is None:
            self.base_joints = every_other_column(self.layout, self.base_plane_deg)
        if self.merged_pair:
            require("merged_pair", self.merged_pair, f"whole [1, {self.layout.count - 1}]")
            centre = self.merged_pair * self.layout.width  # the main joint between the pair
            self.base_joints = merged(self.base_joints, self.merged_pair,
                                      centre * math.tan(math.radians(self.base_plane_deg)))
        for k, j in enumerate(self.base_joints):
            if not 1 <= j.first <= j.last <= self.layout.count:
                raise ValueError(f"base_joints[{k}] = columns {j.first}-{j.last} is invalid: they must be columns "
                                 f"1 <= first <= last <= {self.layout.count}")
            require(f"base_joints[{k}].height", j.height, "[0, inf)")

    def foundation(self) -> list[tuple[float, float]]:
        """The rock under the table plane: toe, foot of the right side, top of the right side."""
        a = math.radians(self.shape.tilt_deg)
        toe_x, length = self.layout.toe_x, self.layout.count * self.layout.width  # along the table
        base = length * math.cos(a)  # the horizontal base's length
        foot = (toe_x - base * math.cos(a), -base * math.sin(a))
        return [(toe_x, 0.0), foot, (toe_x - length, 0.0)]

    def section(self) -> list[tuple[float, float]]:
        """The whole section, counter-clockwise: the foundation's base and right side, the columns."""
        foot = self.foundation()[1]
        columns_ = self.layout.section()  # from the back column's foot on the table, to the toe, up the steps
        return [columns_[0], foot] + columns_[1:]

    def expected_discs(self) -> int:
        return packing.disc_count(geometry.region(self.section()).area(), self.rmin, self.rmax, self.porosity)

    def build(self) -> columns.ColumnLayout:
        """The bonded rock (no joints yet: ``settled`` installs them) in an empty scene; returns its layout."""
        discs = packed_discs(self.section(), self.rmin, self.rmax, self.porosity, self.seed, self.z_order)
        toe, foot, back = self.foundation()
        ids = bonded_rock(discs, self.rock, self.bond_gap, [(toe, foot), (foot, back)], self.rmax, self.damping,
                          self.timestep_safety)
        print(f"equivalent slope: {len(ids)} discs, {self.layout.count} columns", flush=True)
        return self.layout

    def main_joints(self) -> JointSetGeometry:
        """The joints between neighbouring columns, from the table plane (or the horizontal base,
        ``joints_into_foundation``) up to the taller one's top."""
        layout = self.layout
        ks = range(1, layout.count)
        tops = [max(layout.heights[k - 1], layout.heights[k]) for k in ks]
        xs = [layout.span(k)[0] for k in ks]
        bottoms = [self.foundation_floor(x) if self.joints_into_foundation else 0.0 for x in xs]
        return JointSetGeometry(dip=90, segmentStarts=list(zip(xs, bottoms)), segmentEnds=list(zip(xs, tops)))

    def foundation_floor(self, x: float) -> float:
        """The foundation's lower edge below ``x``: the horizontal base from the toe to its foot,
        then the vertical side from the foot up to the table plane."""
        toe, foot, back = self.foundation()
        if x >= foot[0]:
            return foot[1] * (toe[0] - x) / (toe[0] - foot[0])
        return foot[1] * (x - back[0]) / (foot[0] - back[0])

    def base_joint_set(self) -> JointSetGeometry:
        spans = [(self.layout.span(j.last)[0], self.layout.span(j.first)[1], j.height) for j in self.base_joints]
        return JointSetGeometry(dip=0, segmentStarts=[(left, y) for left, _, y in spans],
                                segmentEnds=[(right, y) for _, right, y in spans])

    def settled(self) -> None:
        """Install the joints in the settled, bonded rock (thesis §5.3.2: "in the final step")."""
        t, (toe, foot, back) = self.rock["thickness"], self.foundation()
        lo, hi = (back[0] - 1, foot[1] - 1), (toe[0] + 1, max(self.layout.heights) + 1)
        sets = [(self.main_joints(), self.main.material(self.joint_gap, t))]
        if self.base_joints:  # a set without segments would be one persistent joint along the table plane
            sets.append((self.base_joint_set(), self.base.material(self.joint_gap, t)))
        joints.install_joints(sets, lo=lo, hi=hi, face_closure=self.face_closure)
        print(f"joints installed: {len(self.layout.heights) - 1} main, {len(self.base_joints)} base", flush=True)

    def column_top_bands(self, layout: columns.ColumnLayout) -> dict[str, list[int]]:
        return column_top_bands(layout, self.rmax)

    def merged_pair_distance(self, n1: int) -> float:
        """D/H of Table 5-7's case (N2-N1): the horizontal distance from the toe to the main joint
        between columns n1 and n1 + 1 on the table plane, over H."""
        return n1 * self.layout.width * math.cos(math.radians(self.shape.tilt_deg)) / self.shape.height


# from_params' parameters that act only once the rock has settled (tilt_run.settled_store)
JOINT_INPUTS = ("base_joints", "base_plane_deg", "merged_pair", "main_joint_friction", "joint_stiffness_scale",
                "joint_gap", "joints_into_foundation", "face_closure", "model")


def from_params(p: Any, thesis: Any) -> EquivalentSlope:
    """The model from a parameter set ``p`` (``yade.params.table``; the names of
    examples/params.py's EQUIVALENT_SLOPE) and the thesis' tables ``thesis`` (examples/params.py).
    ``strength_factor`` scales Table 5-5's bond tensile strength and cohesion together;
    ``main_joint_friction`` is the main joints' (Table 5-6: 0.12; Table 5-10 varies it from 0);
    ``spacing`` 0 is the thesis' 0.047 m; ``base_joints`` 'every_other', 'none' or explicit
    (``parse_base_joints``), ``base_plane_deg`` and ``merged_pair`` as EquivalentSlope's."""
    require("strength_factor", p.strength_factor, "(0, inf)")
    require("main_joint_friction", p.main_joint_friction, "[0, inf)")
    require("joints_into_foundation", p.joints_into_foundation, "whole [0, 1]")
    require("joint_stiffness_scale", p.joint_stiffness_scale, "(0, 1]")
    require("joint_gap", p.joint_gap, "[0, inf)")
    require("face_closure", p.face_closure, "whole [0, 1]")
    rock = dict(thesis.TABLE_5_5)
    rock["bondTensileStrength"] *= p.strength_factor
    rock["bondCohesion"] *= p.strength_factor
    joint = thesis.TABLE_5_6
    thesis_shape = thesis.EQUIVALENT_SLOPE_SHAPE
    shape = SlopeShape(**{**thesis_shape, "spacing": p.spacing or thesis_shape["spacing"]})
    base = None if p.base_joints == "every_other" else parse_base_joints(p.base_joints)
    return EquivalentSlope(
        shape=shape, rock=rock,
        main=JointMaterial(p.joint_stiffness_scale * joint["main"][0], p.main_joint_friction),
        base=JointMaterial(p.joint_stiffness_scale * joint["base"][0], joint["base"][1]),
        joint_gap=p.joint_gap, bond_gap=thesis.TABLE_5_5_BOND_GAP, rmin=p.rmin, rmax=p.rmax, porosity=p.porosity,
        seed=p.seed, base_joints=base, base_plane_deg=p.base_plane_deg, merged_pair=p.merged_pair,
        joints_into_foundation=bool(p.joints_into_foundation), z_order=bool(p.z_order),
        timestep_safety=p.timestep_safety, damping=p.damping, face_closure=bool(p.face_closure))


def protocol(p: Any, model: EquivalentSlope) -> tilt_run.TiltProtocol:
    """The run: the bonded slope settles at the model's tilt with ``settle_damping``, its joints
    are installed, then one stage at the same tilt with ``damping`` (TiltRun's criteria: it
    stands or fails), ``post_failure_time`` after a failure."""
    tilt = model.shape.tilt_deg
    return tilt_run.TiltProtocol(start_tilt=tilt, step=1.0, max_tilt=tilt, tilt_rate=1.0, stage_rate=0.0,
                                 damping=p.damping, settle_damping=p.settle_damping, arrest_time=0.0,
                                 post_failure_time=p.post_failure_time, checkpoint_every=p.checkpoint_every,
                                 max_wall_time=p.max_wall_time, exact_resume=p.exact_resume, settle_tilt=tilt)


def parse_base_joints(text: str) -> list[BaseJoint]:
    """Base joints written as a batch table can hold them: ``first-last[@height]`` separated by
    ``;`` (``1-1;3-3;5-6@0.13``), or ``none``."""
    if text == "none":
        return []
    found = []
    for item in text.split(";"):
        span, _, height = item.partition("@")
        first, _, last = span.partition("-")
        try:
            found.append(BaseJoint(int(first), int(last or first), float(height or 0)))
        except ValueError:
            raise ValueError(f"base_joints = {text!r} is invalid: write 'every_other', 'none' or items "
                             "'first-last[@height]' separated by ';'") from None
    return found
