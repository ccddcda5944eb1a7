"""A cliff of jointed columns standing on a softer layer (thesis §5.4.1, Ihlara Valley): rock
layers one above the other, vertical joints cutting the columns, a bedding joint under them, and
a zone of the soft layer at the toe that is weathered (weaker rock) or eroded (removed).

Frame: y = 0 on the bedding plane (the layer under it is the foundation, as the equivalent
slope's), x to the right, the cliff's face on the right at ``face_x``; columns numbered from the
face, so that the tilting table's stage criteria, failure analysis and pictures apply at a level
table (tilt 0). The left side is held in x, the base in x and y (§5.4.1.3).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from yade.wrapper import JointSetGeometry, ParallelBondMat

from toppling.build import boundary, columns, engines, geometry, joints, packing
from toppling.build.discs import add_discs
from toppling.checks import require
from toppling.models.tilting_table import BondedDiscs, JointMaterial, bond_in_scene, column_top_bands, packed_discs


@dataclass(frozen=True)
class Layer:
    """Rock (ParallelBondMat's keyword arguments) from the layer below up to ``top`` [m]."""
    top: float
    rock: dict[str, Any]


@dataclass(frozen=True)
class Zone:
    """A box of the section (x0, x1, y0, y1) [m] of other rock (weathering) or, with rock None,
    left empty (erosion: the cliff is built, settled bonded and jointed with the hollow under it)."""
    box: tuple[float, float, float, float]
    rock: dict[str, Any] | None


@dataclass
class LayeredCliff(BondedDiscs):
    """``width`` × (``foundation`` below the bedding, ``layers`` above it) [m]; the cliff's face at
    ``face_x``, the ground in front of it at y = 0; ``column_width`` [m] columns from the face
    back to x = 0, cut by ``vertical`` joints from the bedding to the top and standing on the
    ``bedding`` joint; ``zone`` at the toe; its discs as ``BondedDiscs``."""
    width: float
    foundation: Layer  # its ``top`` is its thickness below the bedding
    layers: list[Layer]
    face_x: float
    column_width: float
    vertical: JointMaterial
    bedding: JointMaterial
    zone: Zone | None
    timestep_safety: float = 0.5
    damping: float = 0.0
    layout: columns.ColumnLayout = None

    def __post_init__(self):
        super().__post_init__()
        engines.check_safety(self.timestep_safety, "timestep_safety")
        require("face_x", self.face_x, f"(0, {self.width:g})")
        require("column_width", self.column_width, f"(0, {self.face_x:g}]")
        count = round(self.face_x / self.column_width)
        if abs(count * self.column_width - self.face_x) > 1e-9 * self.face_x:
            raise ValueError(f"column_width = {self.column_width} is invalid: face_x = {self.face_x} must hold a whole "
                             "number of columns")
        for k, layer in enumerate(self.layers):
            require(f"layers[{k}].top", layer.top, f"({self.layers[k - 1].top if k else 0:g}, inf)")
        self.layout = columns.ColumnLayout(self.face_x, self.column_width, [self.height] * count)

    @property
    def height(self) -> float:
        return self.layers[-1].top

    def section(self) -> list[tuple[float, float]]:
        depth = self.foundation.top
        return [(0.0, -depth), (self.width, -depth), (self.width, 0.0), (self.face_x, 0.0), (self.face_x, self.height),
                (0.0, self.height)]

    def expected_discs(self) -> int:
        return packing.disc_count(geometry.region(self.section()).area(), self.rmin, self.rmax, self.porosity)

    def rock_at(self, x: float, y: float) -> dict[str, Any]:
        if self.zone is not None and self.zone.rock is not None and _inside(self.zone.box, x, y):
            return self.zone.rock
        return next((layer.rock for layer in self.layers if y < layer.top), self.layers[-1].rock) if y >= 0 \
            else self.foundation.rock

    def build(self) -> columns.ColumnLayout:
        """The bonded rock, held at its left side and base (no joints yet: ``settled`` installs them)."""
        discs = packed_discs(self.section(), self.rmin, self.rmax, self.porosity, self.seed, False)
        materials: dict[int, ParallelBondMat] = {}
        ids = []
        eroded = self.zone is not None and self.zone.rock is None
        for x, y, r in discs:
            if eroded and _inside(self.zone.box, x, y):
                continue
            rock = self.rock_at(x, y)
            material = materials.setdefault(id(rock), ParallelBondMat(**rock))
            ids += add_discs([(x, y, r)], material)
        ids = bond_in_scene(ids, self.bond_gap, self.damping, self.timestep_safety)
        depth = self.foundation.top
        boundary.fix(boundary.near([((0.0, -depth), (self.width, -depth))], self.rmax, ids), "xy")
        boundary.fix(boundary.near([((0.0, -depth), (0.0, self.height))], self.rmax, ids), "x")
        print(f"layered cliff: {len(ids)} discs, {self.layout.count} columns", flush=True)
        return self.layout

    def settled(self) -> None:
        """Install the joints in the settled, bonded rock (as the thesis, §5.4.1.3)."""
        t = self.layers[0].rock["thickness"]
        xs = [self.layout.span(k)[0] for k in range(1, self.layout.count)]
        vertical = JointSetGeometry(dip=90, segmentStarts=[(x, 0.0) for x in xs],
                                    segmentEnds=[(x, self.height) for x in xs])
        bedding = JointSetGeometry(dip=0, segmentStarts=[(0.0, 0.0)], segmentEnds=[(self.face_x, 0.0)])
        lo, hi = (-1.0, -self.foundation.top - 1), (self.width + 1, self.height + 1)
        joints.install_joints([(vertical, self.vertical.material(self.joint_gap, t)),
                               (bedding, self.bedding.material(self.joint_gap, t))], lo=lo, hi=hi)
        print(f"joints installed: {len(xs)} vertical, 1 bedding", flush=True)

    def column_top_bands(self, layout: columns.ColumnLayout) -> dict[str, list[int]]:
        return column_top_bands(layout, self.rmax)


def ihlara_from_params(p: Any, thesis: Any) -> LayeredCliff:
    """The Ihlara Valley's cliff (thesis §5.4.1) from a parameter set ``p`` (``case``: 'intact',
    'weathered' or 'eroded'; ``weathered_strength_factor`` divides the weathered tuff's bond
    strengths; ``joint_gap`` [m]; ``joint_shear_stiffness`` [N/m³], 0: Table 5-13's; ``porosity``,
    ``rmin``, ``rmax``, ``bond_gap`` [m], ``seed``, ``timestep_safety``, ``damping``) and the thesis' numbers
    (``thesis``: examples/params.py)."""
    if p.case not in ("intact", "weathered", "eroded"):
        raise ValueError(f"case = {p.case!r} is invalid: it must be 'intact', 'weathered' or 'eroded'")
    require("weathered_strength_factor", p.weathered_strength_factor, "(0, inf)")
    require("joint_gap", p.joint_gap, "[0, inf)")
    require("joint_shear_stiffness", p.joint_shear_stiffness, "[0, inf)")
    section, rocks, joint = thesis.IHLARA_SECTION, thesis.TABLE_5_12, thesis.TABLE_5_13
    weathered = dict(rocks["weathered"])
    for key in ("bondTensileStrength", "bondCohesion"):
        weathered[key] /= p.weathered_strength_factor
    box = (section["face_x"] - 1.5 * section["column_width"], section["width"], -section["weathered_depth"], 0.0)
    kn, ks = joint["vertical"][0], p.joint_shear_stiffness or joint["vertical"][1]  # the two sets share them
    return LayeredCliff(
        width=section["width"], foundation=Layer(section["tuff"], rocks["tuff"]),
        layers=[Layer(section["ignimbrite"], rocks["ignimbrite"]),
                Layer(section["ignimbrite"] + section["ash"], rocks["ash"])],
        face_x=section["face_x"], column_width=section["column_width"],
        vertical=JointMaterial(kn, joint["vertical"][2], ks), bedding=JointMaterial(kn, joint["bedding"][2], ks),
        zone=None if p.case == "intact" else Zone(box, weathered if p.case == "weathered" else None),
        joint_gap=p.joint_gap, bond_gap=p.bond_gap, rmin=p.rmin, rmax=p.rmax,
        porosity=p.porosity, seed=p.seed, timestep_safety=p.timestep_safety, damping=p.damping)


def _inside(box: tuple[float, float, float, float], x: float, y: float) -> bool:
    x0, x1, y0, y1 = box
    return x0 <= x <= x1 and y0 <= y <= y1
