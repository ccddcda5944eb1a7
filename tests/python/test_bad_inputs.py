"""Every bad input to the public API is refused with an error that names the parameter and its
valid range, before anything runs. The list, by label, is docs/user_guide.md's "What is
refused"; a test keeps the two the same."""
import math
import os
import tempfile
from types import SimpleNamespace

import pytest
from conftest import REPO, ROCK
from examples import params
from yade import O, pack
from yade.utils import readParamsFromTable
from yade.wrapper import JointSetGeometry, ParallelBondMat, PolygonRegion, SmoothJointMat

from toppling.build import bonding, boundary, columns, engines, joints, packing
from toppling.build.discs import disc
from toppling.io.params import check
from toppling.load import tilting
from toppling.models import equivalent_slope, incline
from toppling.run import tilt_run
from toppling.run.checkpoint import Checkpoint
from toppling.run.steps import run_checked, run_steps

SQUARE = [(0, 0), (1, 0), (1, 1), (0, 1)]
HOLE = [(0.4, 0.4), (0.6, 0.4), (0.6, 0.6), (0.4, 0.6)]
def slope(**changes):
    """The equivalent slope's base model with ``changes`` to its parameters."""
    return equivalent_slope.from_params(SimpleNamespace(**{**params.EQUIVALENT_SLOPE, **changes}), params)


PROTOCOL = dict(start_tilt=20.0, step=2.0, max_tilt=40.0, tilt_rate=50.0, stage_rate=10.0, damping=0.0,
                settle_damping=0.7, arrest_time=0.0, post_failure_time=0.3, checkpoint_every=600.0)


def polygon(vertices, holes=()):
    return PolygonRegion(vertices=vertices, holeVertices=[p for h in holes for p in h], holeSizes=[len(h) for h in holes])


def joints_with(geometry):
    """Install ``geometry`` in a scene of two discs, inside the box (0, 0)..(1, 1)."""
    O.bodies.append([disc((0.45, 0.5), 0.05, ParallelBondMat(**ROCK)), disc((0.55, 0.5), 0.05, ParallelBondMat(**ROCK))])
    O.engines = engines.engines()
    joints.install_joints([(geometry, SmoothJointMat(normalStiffness=1e9, shearStiffness=1e9))], (0, 0), (1, 1))


def unknown_parameter(tmp_path):
    table = tmp_path / "params.table"
    table.write_text("alph\n30\n")
    readParamsFromTable(f"{table}:2", noTableOk=False, alpha=26.0)


BAD = [  # label, the call, what the error says
    ("rock Young's modulus negative", lambda: ParallelBondMat(young=-1), "ParallelBondMat.young = -1 is invalid: it must be > 0"),
    ("rock friction angle 2 rad", lambda: ParallelBondMat(frictionAngle=2),
     "ParallelBondMat.frictionAngle = 2 is invalid: it must be in [0, pi/2) rad"),
    ("rock damping 1", lambda: ParallelBondMat(normalDamping=1), "ParallelBondMat.normalDamping = 1 is invalid: it must be in [0, 1)"),
    ("bond tensile strength negative", lambda: ParallelBondMat(bondTensileStrength=-5),
     "ParallelBondMat.bondTensileStrength = -5 is invalid: it must be >= 0"),
    ("disc thickness 0", lambda: ParallelBondMat(thickness=0), "ParallelBondMat.thickness = 0 is invalid: it must be > 0"),
    ("bond kn/ks NaN", lambda: ParallelBondMat(bondKnKs=math.nan), "ParallelBondMat.bondKnKs = nan is invalid: it must be > 0"),
    ("joint normal stiffness 0", lambda: SmoothJointMat(normalStiffness=0),
     "SmoothJointMat.normalStiffness = 0 is invalid: it must be > 0"),
    ("joint friction angle negative", lambda: SmoothJointMat(frictionAngle=-0.1),
     "SmoothJointMat.frictionAngle = -0.1 is invalid: it must be in [0, pi/2) rad"),
    ("joint dilation angle 1.6 rad", lambda: SmoothJointMat(dilationAngle=1.6),
     "SmoothJointMat.dilationAngle = 1.6 is invalid: it must be in [0, pi/2) rad"),
    ("joint gap negative", lambda: SmoothJointMat(gap=-1e-4), "SmoothJointMat.gap = -0.0001 is invalid: it must be >= 0"),
    ("polygon self-intersecting", lambda: polygon([(0, 0), (1, 1), (1, 0), (0, 1)]),
     "PolygonRegion.vertices: polygon is self-intersecting"),
    ("polygon with a repeated vertex", lambda: polygon([(0, 0), (1, 0), (1, 0), (0, 1)]),
     "PolygonRegion.vertices: polygon has a repeated vertex at index 1"),
    ("polygon of two vertices", lambda: polygon([(0, 0), (1, 0)]), "PolygonRegion.vertices: polygon needs at least 3 vertices"),
    ("polygon without area", lambda: polygon([(0, 0), (1, 0), (2, 0)]),
     "PolygonRegion.vertices: polygon has no area: its vertices lie on one line"),
    ("polygon vertex NaN", lambda: polygon([(0, 0), (1, 0), (0, math.nan)]),
     "PolygonRegion.vertices: vertex 2 is not a finite point"),
    ("hole outside the polygon", lambda: polygon(SQUARE, [[(2, 2), (3, 2), (3, 3)]]),
     "PolygonRegion.holeVertices: hole 0 is not inside the outer polygon"),
    ("hole across the boundary", lambda: polygon(SQUARE, [[(0.9, 0.5), (1.5, 0.5), (1.5, 0.7)]]),
     "PolygonRegion.holeVertices: hole 0 is not inside the outer polygon"),
    ("holes overlapping", lambda: polygon(SQUARE, [HOLE, [(0.5, 0.5), (0.7, 0.5), (0.7, 0.7)]]),
     "PolygonRegion.holeVertices: hole 1 overlaps hole 0"),
    ("hole sizes not matching", lambda: PolygonRegion(vertices=SQUARE, holeVertices=HOLE, holeSizes=[5]),
     "PolygonRegion.holeSizes does not match holeVertices"),
    ("joint spacing negative", lambda: JointSetGeometry(spacing=-0.1),
     "JointSetGeometry.spacing = -0.1 is invalid: it must be >= 0 m"),
    ("joint dip 200 deg", lambda: JointSetGeometry(dip=200), "JointSetGeometry.dip = 200 is invalid: it must be in [-180, 180] deg"),
    ("joint dip NaN", lambda: JointSetGeometry(dip=math.nan), "JointSetGeometry.dip = nan is invalid"),
    ("joint length 0 (persistence 0)", lambda: JointSetGeometry(spacing=0.1, jointLength=0),
     "JointSetGeometry.jointLength = 0 is invalid: it must be > 0 m (the persistence"),
    ("rock bridge negative (persistence > 1)", lambda: JointSetGeometry(spacing=0.1, jointLength=1, bridgeLength=-1),
     "JointSetGeometry.bridgeLength = -1 is invalid: it must be >= 0 m (the persistence"),
    ("explicit joint outside the box", lambda: joints_with(JointSetGeometry(segmentStarts=[(0.5, 0)], segmentEnds=[(0.5, 2)])),
     "JointSetGeometry.segmentStarts[0], segmentEnds[0] = (0.5, 0), (0.5, 2) are invalid: an explicit joint must lie "
     "inside the box"),
    ("explicit joint without an end", lambda: joints_with(JointSetGeometry(segmentStarts=[(0.5, 0)])),
     "JointSetGeometry: segmentStarts and segmentEnds must have the same length"),
    ("packing Rmin > Rmax", lambda: packing.pack_polygon(polygon(SQUARE), 0.02, 0.01, 0.2),
     "rmax = 0.01 is invalid: it must be in [0.02, inf)"),
    ("packing Rmin 0", lambda: packing.pack_polygon(polygon(SQUARE), 0, 0.01, 0.2), "rmin = 0 is invalid: it must be in (0, inf)"),
    ("packing porosity 1", lambda: packing.pack_polygon(polygon(SQUARE), 0.01, 0.02, 1.0),
     "porosity = 1.0 is invalid: it must be in (0, 1)"),
    ("packing porosity unreachable", lambda: packing.pack_polygon(polygon([(0, 0), (0.1, 0), (0.1, 0.1), (0, 0.1)]), 0.004,
                                                                  0.008, 0.02), "porosity = 0.02 is unreachable"),
    ("packing too many discs for the memory", lambda: packing.pack_polygon(polygon(SQUARE), 1e-6, 2e-6, 0.2),
     "rmin = 1e-06, rmax = 2e-06 are invalid for this polygon: they make about 1.09e+11 discs"),  # 0.8 m2 / (pi 7/3 um2)
    ("packing Rmax larger than the polygon", lambda: packing.pack_polygon(polygon(SQUARE), 0.1, 0.5, 0.2),
     "rmax = 0.5 is invalid: it must be in (0, 0.25]"),
    ("packing an unbounded predicate", lambda: packing.pack_predicate(pack.notInNotch((0, 0, 0), (1, 0, 0), (0, 1, 0), 1), 0.01,
                                                                      0.02), "it must be bounded in the xy-plane"),
    ("disc radius 0", lambda: disc((0, 0), 0, ParallelBondMat(**ROCK)), "radius = 0 is invalid: it must be in (0, inf)"),
    ("bond gap negative", lambda: bonding.bond_within_gap(-1e-3), "gap = -0.001 is invalid: it must be in [0, inf)"),
    ("boundary distance negative", lambda: boundary.near([((0, 0), (1, 0))], -1), "distance = -1 is invalid: it must be in [0, inf)"),
    ("boundary dofs 'z'", lambda: boundary.fix([], "z"), "dofs = 'z' is invalid: it must be 'x', 'y' or 'xy'"),
    ("column width 0", lambda: columns.ColumnLayout(toe_x=1, width=0, heights=[0.1]), "width = 0 is invalid: it must be in (0, inf)"),
    ("column height negative", lambda: columns.ColumnLayout(toe_x=1, width=0.1, heights=[0.1, -0.2]),
     "heights[1] = -0.2 is invalid: it must be in (0, inf)"),
    ("local damping 1", lambda: engines.engines(local_damping=1.0), "local_damping = 1.0 is invalid: it must be in [0, 1)"),
    ("time-step safety 0", lambda: engines.engines(safety=0), "safety = 0 is invalid: it must be in (0, 1]"),
    ("tilt 95 deg", lambda: tilting.set_tilt(95), "tilt = 95 is invalid: it must be in [0, 90)"),
    ("start tilt 90 deg", lambda: tilt_run.TiltProtocol(**{**PROTOCOL, "start_tilt": 90.0}),
     "start_tilt = 90.0 is invalid: it must be in [0, 90)"),
    ("settle tilt 95 deg", lambda: tilt_run.TiltProtocol(**{**PROTOCOL, "settle_tilt": 95.0}),
     "settle_tilt = 95.0 is invalid: it must be in [0, 90)"),
    ("slope face leaning out beyond the main joints",
     lambda: equivalent_slope.SlopeShape(height=0.475, joint_dip_deg=55, face_deg=150, top_deg=8, spacing=0.047),
     "face_deg = 150 is invalid: it must be in (55, 145)"),
    ("base joint beyond the last column", lambda: slope(base_joints="3-40"),
     "base_joints[0] = columns 3-40 is invalid: they must be columns 1 <= first <= last <= 22"),
    ("base joints unreadable", lambda: slope(base_joints="x-1"), "base_joints = 'x-1' is invalid"),
    ("slope strength factor 0", lambda: slope(strength_factor=0), "strength_factor = 0 is invalid: it must be in (0, inf)"),
    ("start tilt negative", lambda: tilt_run.TiltProtocol(**{**PROTOCOL, "start_tilt": -5.0}),
     "start_tilt = -5.0 is invalid: it must be in [0, 90)"),
    ("max tilt below the start tilt", lambda: tilt_run.TiltProtocol(**{**PROTOCOL, "max_tilt": 10.0}),
     "max_tilt = 10.0 is invalid: it must be in [20.0, 90)"),
    ("tilt step 0", lambda: tilt_run.TiltProtocol(**{**PROTOCOL, "step": 0.0}), "step = 0.0 is invalid: it must be in (0, inf)"),
    ("loading damping 1", lambda: tilt_run.TiltProtocol(**{**PROTOCOL, "damping": 1.0}),
     "damping = 1.0 is invalid: it must be in [0, 1)"),
    ("post-failure time negative", lambda: tilt_run.TiltProtocol(**{**PROTOCOL, "post_failure_time": -1.0}),
     "post_failure_time = -1.0 is invalid: it must be in [0, inf)"),
    ("stage rate negative", lambda: tilt_run.TiltProtocol(**{**PROTOCOL, "stage_rate": -1.0}),
     "stage_rate = -1.0 is invalid: it must be in [0, inf)"),
    ("arrest time negative", lambda: tilt_run.TiltProtocol(**{**PROTOCOL, "arrest_time": -1.0}),
     "arrest_time = -1.0 is invalid: it must be in [0, inf)"),
    ("checkpoint interval 0", lambda: tilt_run.TiltProtocol(**{**PROTOCOL, "checkpoint_every": 0.0}),
     "checkpoint_every = 0.0 is invalid: it must be in (0, inf)"),
    ("wall-time limit negative", lambda: tilt_run.TiltProtocol(**{**PROTOCOL, "max_wall_time": -1.0}),
     "max_wall_time = -1.0 is invalid: it must be in [0, inf)"),
    ("tilt rate of the wrong type", lambda: tilt_run.TiltProtocol(**{**PROTOCOL, "tilt_rate": "fast"}),
     "tilt_rate = 'fast' is invalid: it must be a number in (0, inf)"),
    ("stage chunk negative", lambda: tilting.StageCriteria(chunk=-0.02), "chunk = -0.02 is invalid: it must be in (0, inf)"),
    ("fail columns 0", lambda: tilting.StageCriteria(fail_columns=0), "fail_columns = 0 is invalid: it must be in [1, inf)"),
    ("ramp duration negative", lambda: tilting.ramp(0, 10, -1.0), "duration = -1.0 is invalid: it must be in (0, inf)"),
    ("run a negative number of steps", lambda: run_steps(-10), "steps = -10 is invalid: it must be in [0, inf)"),
    ("run a negative time", lambda: run_checked(-0.1), "seconds = -0.1 is invalid: it must be in (0, inf)"),
    ("time step 0", lambda: (setattr(O, "dt", 0.0), run_checked(0.1)), "O.dt = 0.0: the time step must be > 0 s"),
    ("resume 2", lambda: Checkpoint(tempfile.mkdtemp()).continues({}, 2), "resume = 2 is invalid: it must be -1"),
    ("example parameter of the wrong type", lambda: check(SimpleNamespace(alpha="steep"), alpha="[0, 90)"),
     "alpha = 'steep' is invalid: it must be a number in [0, 90)"),
    ("example parameter not whole", lambda: check(SimpleNamespace(discs=2.5), discs="whole [2, inf)"),
     "discs = 2.5 is invalid: it must be a whole number in [2, inf)"),
    ("discs too large for the block", lambda: incline.build(0.2, 0.2, 0.2 / 3 / 2.5, 0.2 / 3, ROCK, 0.0, porosity=0.25),
     "rmax = 0.0666667 is too large for a 0.2 x 0.2 m block: no disc of it is bonded to another"),
]


@pytest.mark.parametrize("label, call, says", BAD, ids=[label for label, _, _ in BAD])
def test_a_bad_input_is_refused_by_name_and_range(empty_scene, label, call, says):
    with pytest.raises((ValueError, RuntimeError)) as refused:
        call()
    assert says in str(refused.value)


def test_an_unknown_example_parameter_is_refused_by_name(tmp_path):
    with pytest.raises(NameError, match="Parameter `alph' has no default value assigned"):
        unknown_parameter(tmp_path)


def test_a_clockwise_polygon_is_the_same_region_as_its_counter_clockwise_twin():
    ccw, cw = polygon(SQUARE), polygon(SQUARE[::-1])
    assert cw.area() == ccw.area() == 1.0
    points = [(0.5, 0.5), (1.5, 0.5), (0.99, 0.2), (1.0, 0.5), (-0.1, 0.9)]  # (1, 0.5): on an edge
    assert cw.containsMany(points, 0.0) == ccw.containsMany(points, 0.0)


def test_the_user_guide_lists_every_refused_input():
    with open(os.path.join(REPO, "docs", "user_guide.md")) as f:
        guide = f.read()
    labels = [label for label, _, _ in BAD] + ["unknown example parameter"]
    assert [label for label in labels if f"| {label} |" not in guide] == []
    assert f"{len(labels)} bad inputs" in guide
