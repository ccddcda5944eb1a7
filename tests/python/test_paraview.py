"""The ParaView series reads back with VTK: counts and fields of discs, bonds, cracks and joints."""
import json
import math
import os
import xml.etree.ElementTree as ET

import pytest
from lattice import R, material, pull_until_broken
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from yade import O
from yade.wrapper import JointSetGeometry, SmoothJointMat

from toppling.build import bonding, boundary, engines, joints
from toppling.build.discs import disc
from toppling.io import paraview
from toppling.run.steps import run_steps


def read(path):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def field(grid, name, cells=False):
    data = grid.GetCellData() if cells else grid.GetPointData()
    return vtk_to_numpy(data.GetArray(name))


def test_series_of_discs_bonds_and_joints(empty_scene, tmp_path):
    # pair A (x = 0): a weak bond, pulled apart until it breaks in tension;
    # pair B (x = 4R): a smooth joint; pair C (x = 8R): an intact bond.
    rock = material(bondTensileStrength=1e4)
    for x in (0, 4 * R, 8 * R):
        O.bodies.append([disc((x, 0), R, rock, fixed=True), disc((x, 2 * R), R, rock, fixed=x > 0)])
    O.engines = engines.engines(gravity=(0, 0, 0))
    bonding.bond_within_gap(1e-9)
    joint = JointSetGeometry(segmentStarts=[(3 * R, R)], segmentEnds=[(5 * R, R)])
    system = joints.install_joints([(joint, SmoothJointMat(frictionAngle=math.radians(20)))],
                                   lo=(-R, -R), hi=(10 * R, 4 * R))
    series = paraview.ParaViewSeries(str(tmp_path), system.blockOfBody)
    series.snapshot()
    pull_until_broken(1)
    run_steps(10)
    paths = series.snapshot()
    assert [os.path.basename(p) for p in paths] == ["discs_00001.vtu", "bonds_00001.vtu", "cracks_00001.vtu",
                                                    "joints_00001.vtu"]

    discs = read(paths[0])
    assert discs.GetNumberOfPoints() == 6
    assert field(discs, "radius") == pytest.approx([R] * 6)
    assert field(discs, "displacement")[1][1] > 0 and field(discs, "velocity")[1][1] == pytest.approx(0.01)
    assert list(field(discs, "fixed")) == [1, 1, 1, 1, 1, 1]  # disc 1 is driven
    assert len(field(discs, "block")) == 6
    bonds = read(paths[1])
    assert bonds.GetNumberOfCells() == 1  # C intact; A's broken bond is not drawn between its parted discs
    assert len(field(bonds, "sigma_max", cells=True)) == 1
    cracks = read(paths[2])  # A's bond, where it broke: between the two discs, across the pull
    assert cracks.GetNumberOfCells() == 1
    assert vtk_to_numpy(cracks.GetPoints().GetData())[0][:2] == pytest.approx((0, R), abs=1e-3 * R)
    assert list(field(cracks, "mode", cells=True)) == [2]  # tension
    assert field(cracks, "normal", cells=True)[0] == pytest.approx((0, 1, 0), abs=1e-6)
    assert field(cracks, "size", cells=True)[0] == pytest.approx(2 * R)  # the bond's width, 2 lambda R
    assert 0 < field(cracks, "time", cells=True)[0] < O.time
    joint_grid = read(paths[3])  # B's joint, drawn along its trace y = R through the contact
    assert joint_grid.GetNumberOfCells() == 1
    ends = vtk_to_numpy(joint_grid.GetPoints().GetData())[:, :2]
    assert sorted(ends[:, 0]) == pytest.approx([3 * R, 5 * R]) and ends[:, 1] == pytest.approx([R, R])
    assert list(field(joint_grid, "set", cells=True)) == [0]
    assert len(field(joint_grid, "slip", cells=True)) == 1

    for kind in paraview.KINDS:
        entries = ET.parse(tmp_path / f"{kind}.pvd").getroot().find("Collection")
        assert [e.get("file") for e in entries] == [f"{kind}_00000.vtu", f"{kind}_00001.vtu"]
        assert float(entries[1].get("timestep")) == pytest.approx(O.time)


def test_fixed_flag_marks_discs_held_or_driven_by_a_boundary_condition(empty_scene, tmp_path):
    """Free, held by boundary.fix (the table's layer), driven by boundary.move, non-dynamic."""
    rock = material()
    O.bodies.append([disc((4 * k * R, 0), R, rock, fixed=k == 3) for k in range(4)])
    boundary.fix([1], "xy")
    boundary.move([2], (0, 1e-3), "y")
    O.engines = engines.engines(gravity=(0, 0, 0))
    discs = read(paraview.ParaViewSeries(str(tmp_path)).snapshot()[0])
    assert list(field(discs, "fixed")) == [0, 1, 1, 1]


def test_resumed_series_continues_numbering_and_displacements(empty_scene, tmp_path):
    O.bodies.append([disc((0, 0), R, material()), disc((4 * R, 0), R, material())])
    O.engines = engines.engines()
    series = paraview.ParaViewSeries(str(tmp_path))
    series.snapshot()
    saved = json.loads(json.dumps(series.state()))
    O.bodies[0].state.pos = (0.5 * R, 0, 0)
    resumed = paraview.ParaViewSeries(str(tmp_path), state=saved)
    discs = read(resumed.snapshot()[0])
    assert field(discs, "displacement")[0] == pytest.approx((0.5 * R, 0, 0))
    entries = ET.parse(tmp_path / "discs.pvd").getroot().find("Collection")
    assert [e.get("file") for e in entries] == ["discs_00000.vtu", "discs_00001.vtu"]
