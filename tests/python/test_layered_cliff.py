"""toppling.models.layered_cliff: layers by height, a weathered or eroded zone, the boundary and
the joints of a cliff of columns (the Ihlara Valley's scene, thesis §5.4.1)."""
import pytest
from yade import O
from yade.wrapper import SmoothJointPhys

from toppling.build import joints
from toppling.models.layered_cliff import Layer, LayeredCliff, Zone
from toppling.models.tilting_table import JointMaterial

ROCK = dict(density=2000.0, young=1e8, knKs=1.2, bondYoung=1e8, bondKnKs=1.2, bondTensileStrength=1e6,
            bondCohesion=1e6, thickness=1.0)


def cliff(zone_rock) -> LayeredCliff:
    soft, cap, top = dict(ROCK, density=1800.0), dict(ROCK, density=2200.0), dict(ROCK, density=1600.0)
    return LayeredCliff(width=3.0, foundation=Layer(0.5, soft), layers=[Layer(1.0, cap), Layer(1.2, top)],
                        face_x=2.0, column_width=0.5, vertical=JointMaterial(1e9, 0.5, 1e7),
                        bedding=JointMaterial(1e9, 0.5, 1e7), zone=Zone((1.25, 3.0, -0.2, 0.0), zone_rock),
                        joint_gap=0.0, bond_gap=0.005, rmin=0.03, rmax=0.05, porosity=0.18, seed=1)


def test_layers_zone_boundary_and_joints(empty_scene):
    model = cliff(dict(ROCK, density=1000.0))
    layout = model.build()
    assert layout.count == 4 and layout.heights == [1.2] * 4
    density = {round(b.material.density) for b in O.bodies if b is not None}
    assert density == {1000, 1600, 1800, 2200}
    for b in O.bodies:
        x, y = b.state.pos[0], b.state.pos[1]
        expected = 1000 if 1.25 <= x and -0.2 <= y <= 0 else 1800 if y < 0 else 2200 if y < 1.0 else 1600
        assert round(b.material.density) == expected
    held = {b.id: b.state.blockedDOFs for b in O.bodies if "x" in b.state.blockedDOFs}  # z, X, Y: every disc
    base = {i for i, dofs in held.items() if "y" in dofs}
    assert base and all(O.bodies[i].state.pos[1] <= -0.5 + 0.05 + 1e-9 for i in base)  # the base: x and y
    assert all(O.bodies[i].state.pos[0] <= 0.05 + 1e-9 for i in set(held) - base) and set(held) - base  # left: x
    model.settled()
    sets = {i.phys.jointSet for i in O.interactions if isinstance(i.phys, SmoothJointPhys)}
    assert sets == {0, 1} and len(set(joints.blocks()) - {-1}) >= 5  # 4 columns and the foundation


def test_an_eroded_zone_is_left_empty(empty_scene):
    cliff(None).build()
    assert not any(1.25 <= b.state.pos[0] and -0.2 <= b.state.pos[1] <= 0 for b in O.bodies if b is not None)


def test_columns_must_fill_the_face(empty_scene):
    with pytest.raises(ValueError, match="face_x = 2.0 must hold a whole number of columns"):
        LayeredCliff(width=3.0, foundation=Layer(0.5, ROCK), layers=[Layer(1.0, ROCK)], face_x=2.0, column_width=0.6,
                     vertical=JointMaterial(1e9, 0.5), bedding=JointMaterial(1e9, 0.5), zone=None, joint_gap=0.0,
                     bond_gap=0.005, rmin=0.03, rmax=0.05, porosity=0.18, seed=1)
