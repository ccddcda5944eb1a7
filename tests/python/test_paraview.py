"""The ParaView series reads back with VTK: counts and fields of discs, bonds and joints."""
import json
import math
import os
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from conftest import load_script
from lattice import R, material
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from yade import O
from yade.wrapper import JointSetGeometry, SmoothJointMat

from toppling import bonding, boundary, columns, joints, paraview, scene


def read(path):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def field(grid, name, cells=False):
    data = grid.GetCellData() if cells else grid.GetPointData()
    return vtk_to_numpy(data.GetArray(name))


def pull_until_broken(body_id: int) -> float:
    """Pull disc ``body_id`` off along +y until a bond breaks; the time of the step that broke it."""
    boundary.move([body_id], (0, 0.01))
    while not scene.bond_law().breakMode:
        when = O.time
        O.step()
    return when


def test_series_of_discs_bonds_and_joints(empty_scene, tmp_path):
    # pair A (x = 0): a weak bond, pulled apart until it breaks in tension;
    # pair B (x = 4R): a smooth joint; pair C (x = 8R): an intact bond.
    rock = material(bondTensileStrength=1e4)
    for x in (0, 4 * R, 8 * R):
        O.bodies.append([scene.disc((x, 0), R, rock, fixed=True), scene.disc((x, 2 * R), R, rock, fixed=x > 0)])
    O.engines = scene.engines(gravity=(0, 0, 0))
    bonding.bond_within_gap(1e-9)
    joint = JointSetGeometry(segmentStarts=[(3 * R, R)], segmentEnds=[(5 * R, R)])
    system = joints.install_joints([(joint, SmoothJointMat(frictionAngle=math.radians(20)))],
                                   lo=(-R, -R), hi=(10 * R, 4 * R))
    series = paraview.ParaViewSeries(str(tmp_path), system.blockOfBody)
    series.snapshot()
    pull_until_broken(1)
    scene.run_steps(10)
    paths = series.snapshot()
    assert [os.path.basename(p) for p in paths] == ["discs_00001.vtu", "bonds_00001.vtu", "joints_00001.vtu"]

    discs = read(paths[0])
    assert discs.GetNumberOfPoints() == 6
    assert field(discs, "radius") == pytest.approx([R] * 6)
    assert field(discs, "displacement")[1][1] > 0 and field(discs, "velocity")[1][1] == pytest.approx(0.01)
    assert list(field(discs, "fixed")) == [1, 1, 1, 1, 1, 1]  # disc 1 is driven
    assert len(field(discs, "block")) == 6
    bonds = read(paths[1])
    assert bonds.GetNumberOfCells() == 2
    assert sorted(field(bonds, "state", cells=True)) == [1, 2]  # C intact, A broken in tension
    assert len(field(bonds, "sigma_max", cells=True)) == 2
    joint_grid = read(paths[2])
    assert joint_grid.GetNumberOfCells() == 1
    assert list(field(joint_grid, "set", cells=True)) == [0]
    assert len(field(joint_grid, "slip", cells=True)) == 1

    for kind in paraview.KINDS:
        entries = ET.parse(tmp_path / f"{kind}.pvd").getroot().find("Collection")
        assert [e.get("file") for e in entries] == [f"{kind}_00000.vtu", f"{kind}_00001.vtu"]
        assert float(entries[1].get("timestep")) == pytest.approx(O.time)


def test_fixed_flag_marks_discs_held_or_driven_by_a_boundary_condition(empty_scene, tmp_path):
    """Free, held by boundary.fix (the table's layer), driven by boundary.move, non-dynamic."""
    rock = material()
    O.bodies.append([scene.disc((4 * k * R, 0), R, rock, fixed=k == 3) for k in range(4)])
    boundary.fix([1], "xy")
    boundary.move([2], (0, 1e-3), "y")
    O.engines = scene.engines(gravity=(0, 0, 0))
    discs = read(paraview.ParaViewSeries(str(tmp_path)).snapshot()[0])
    assert list(field(discs, "fixed")) == [0, 1, 1, 1]


def test_resumed_series_continues_numbering_and_displacements(empty_scene, tmp_path):
    O.bodies.append([scene.disc((0, 0), R, material()), scene.disc((4 * R, 0), R, material())])
    O.engines = scene.engines()
    series = paraview.ParaViewSeries(str(tmp_path))
    series.snapshot()
    saved = json.loads(json.dumps(series.state()))
    O.bodies[0].state.pos = (0.5 * R, 0, 0)
    resumed = paraview.ParaViewSeries(str(tmp_path), state=saved)
    discs = read(resumed.snapshot()[0])
    assert field(discs, "displacement")[0] == pytest.approx((0.5 * R, 0, 0))
    entries = ET.parse(tmp_path / "discs.pvd").getroot().find("Collection")
    assert [e.get("file") for e in entries] == ["discs_00000.vtu", "discs_00001.vtu"]


def pulled_bond() -> None:
    """Two fixed discs bonded, the upper one moving off along +y: a bond in growing tension."""
    rock = material()
    O.bodies.append([scene.disc((0, 0), R, rock, fixed=True), scene.disc((0, 2 * R), R, rock, fixed=True)])
    O.engines = scene.engines(gravity=(0, 0, 0))
    bonding.bond_within_gap(1e-9)
    boundary.move([1], (0, 1e-3))


def test_bond_stress_history_reads_the_series_back(empty_scene, tmp_path, capsys):
    """scripts/bond_stress_history.py: per snapshot the stage's tilt, bond counts and the peak stress."""
    history = load_script("bond_stress_history")
    pulled_bond()
    scene.run_steps(5)  # pulled: the bond carries tension
    series = paraview.ParaViewSeries(str(tmp_path / "paraview"))
    series.snapshot()
    sigma = O.interactions[0, 1].phys.bondSigmaMax
    (tmp_path / "summary.json").write_text(json.dumps({"stages": [{"time": O.time, "tilt": 26.0}]}))
    history.main(str(tmp_path), above=[0.5 * sigma / 1e3, 2 * sigma / 1e3])
    row = capsys.readouterr().out.splitlines()[2].split("|")
    assert sigma > 0 and [c.strip() for c in row[2:5]] == ["26", "1", "0 / 0"]
    assert float(row[5]) == pytest.approx(sigma / 1e3, abs=0.05)
    assert [c.strip() for c in row[7:9]] == ["1", "0"]  # bonds above half and twice its stress


def test_first_crack_reads_the_peaks_and_interpolates_the_tilt(empty_scene, tmp_path):
    """scripts/first_crack.py: the peak bond stress of each stage end (the bond pulled further
    at the second; the snapshot at the start tilt is not one), and the tilt at which it reaches a
    strength between them."""
    first_crack = load_script("first_crack")
    pulled_bond()
    series = paraview.ParaViewSeries(str(tmp_path / "paraview"))
    series.snapshot()  # the slope at the start tilt: not a stage end
    stages, sigma = [], []
    for tilt in (26.0, 28.0):
        scene.run_steps(5)  # pulled further: more tension
        series.snapshot()
        stages.append({"time": O.time, "tilt": tilt})
        sigma.append(O.interactions[0, 1].phys.bondSigmaMax)
    (tmp_path / "summary.json").write_text(json.dumps({"stages": stages}))
    peaks = first_crack.elastic_peaks(str(tmp_path))
    assert [t for t, *_ in peaks] == [26.0, 28.0] and [s[0] for _, s, _ in peaks] == pytest.approx(sigma, rel=1e-6)
    assert peaks[-1][2][0] == pytest.approx([0.0, R], abs=1e-3 * R)  # the bond's midpoint, between the discs
    layout = columns.ColumnLayout(toe_x=0.1, width=0.05, heights=[0.1, 0.1])
    assert first_crack.places(np.array([[0.09, 0.012], [0.01, 0.05]]), layout) == "A-1 1.2 cm, B-2 5.0 cm"
    assert first_crack.crossing_tilt(peaks, 0.25 * sigma[0] + 0.75 * sigma[1]) == pytest.approx(27.5)
    assert first_crack.crossing_tilt(peaks, 0.5 * sigma[0]) == 26.0  # cracked by the first stage: an upper bound
    assert first_crack.crossing_tilt(peaks, 2 * sigma[1]) is None
    two = [(26.0, [3.0, 1.0]), (28.0, [4.0, 2.0]), (30.0, [5.0, 4.0])]  # the second bond from 1 to 4 Pa
    assert first_crack.crossing_tilt(two, 3.0, rank=2) == pytest.approx(29.0)


def test_path_stress_compares_two_runs_at_the_last_stage_both_ended_elastic(empty_scene, tmp_path, capsys):
    """scripts/path_stress.py: two runs' largest stresses at their last common stage, the rise
    into it, and the mean difference over the pairs, in kPa and in degrees of tilt. Run B is the
    bond pulled further than run A, read back from two ParaView series."""
    path_stress = load_script("path_stress")
    a = [(18.0, [70e3]), (20.0, [74e3]), (22.0, [80e3])]
    b = [(20.0, [76e3]), (22.0, [81e3]), (24.0, [90e3])]
    assert path_stress.compare(a, b) == pytest.approx((22.0, 80e3, 81e3, 2.75e3))  # rises 3 and 2.5 kPa/deg
    assert path_stress.compare(a[:1], b) is None and path_stress.compare(a[:1], a[:1]) == (18.0, 70e3, 70e3, None)
    pulled_bond()
    sigma = {}
    for run in ("a", "b"):
        series = paraview.ParaViewSeries(str(tmp_path / run / "paraview"))
        stages = []
        for tilt in (26.0, 28.0):
            scene.run_steps(5)
            series.snapshot()
            stages.append({"time": O.time, "tilt": tilt})
            sigma[run, tilt] = O.interactions[0, 1].phys.bondSigmaMax / 1e3
        (tmp_path / run / "summary.json").write_text(json.dumps({"stages": stages, "failure_tilt_deg": 30.0}))
    path_stress.main([str(tmp_path / run) for run in ("a", "b", "a", "b")])
    lines = capsys.readouterr().out.splitlines()
    difference = sigma["b", 28.0] - sigma["a", 28.0]
    assert difference > 0 and [c.strip() for c in lines[2].split("|")[3:5]] == ["28", f"{sigma['a', 28.0]:.1f}"]
    mean = re.search(r"over 2 pairs: ([-+.\d]+) ± ([.\d]+) kPa.*: ([-+.\d]+) ± ([.\d]+)°", lines[-1]).groups()
    rise = (sigma["a", 28.0] - sigma["a", 26.0] + sigma["b", 28.0] - sigma["b", 26.0]) / 4  # per degree, both runs
    assert [float(v) for v in mean] == pytest.approx([difference, 0.0, difference / rise, 0.0], abs=0.01)


def test_crack_heights_tells_roots_from_bonds_above_the_table(empty_scene, tmp_path, capsys):
    """scripts/crack_heights.py: a bond to a disc within Rmax of the table is a root, one between
    discs 30 mm up is in 20-50 mm. The root is pulled until it breaks: one new crack, at the root."""
    heights = load_script("crack_heights")
    rock = material(bondTensileStrength=1e4)
    low, high = 0.03 - R, 0.03 + R  # the upper pair's bond midpoint is 30 mm above the table
    O.bodies.append([scene.disc((0, 0), R, rock), scene.disc((0, 2 * R), R, rock),
                     scene.disc((4 * R, low), R, rock), scene.disc((4 * R, high), R, rock)])
    boundary.fix([0], "xy")  # held as the table's layer is
    O.engines = scene.engines(gravity=(0, 0, 0))
    bonding.bond_within_gap(1e-9)
    series = paraview.ParaViewSeries(str(tmp_path / "paraview"))
    series.snapshot()
    pull_until_broken(1)
    series.snapshot()
    summary = {"stages": [{"time": O.time, "tilt": 30.0}], "inputs": {"rmax": R}}
    (tmp_path / "summary.json").write_text(json.dumps(summary))
    heights.main(str(tmp_path), top=2)
    rows = [[c.strip() for c in line.split("|")[1:-1]] for line in capsys.readouterr().out.splitlines()[3:]]
    assert rows[0] == ["start", "0", "[0, 0, 0, 0, 0]", "[1, 0, 1, 0, 0]"]  # before the first stage's end
    assert rows[1] == ["30", "1", "[1, 0, 0, 0, 0]", "[0, 0, 1, 0, 0]"]  # only the upper bond is left


def save_bonded_run(folder, ids, reference, equilibrium=None):
    """A tilting-table run's checkpoint as the scripts read it: the scene, and in checkpoint.json
    the discs as bonded (the ParaView series' reference) and the last equilibrium's positions."""
    O.save(str(folder / "checkpoint.yade.bz2"))
    (folder / "checkpoint.json").write_text(json.dumps(
        {"ids": ids, "reference": equilibrium or reference, "series": {"ids": ids, "reference": reference}}))


def test_bond_coordination_counts_neighbours_within_each_gap(empty_scene, tmp_path, capsys):
    """scripts/bond_coordination.py on three discs in a row, 0.5 and 1.5 radii apart at their
    surfaces: no pair within a quarter radius, one within one radius, both within two."""
    coordination = load_script("bond_coordination")
    ids = scene.add_discs([(0, 0, R), (2.5 * R, 0, R), (6 * R, 0, R)], material())
    save_bonded_run(tmp_path, ids, reference=[(0, 0, 0), (2.5 * R, 0, 0), (6 * R, 0, 0)])
    coordination.main(str(tmp_path), [1e3 * g for g in (0.25 * R, R, 2 * R)])
    row = capsys.readouterr().out.splitlines()[-1]
    assert [float(c) for c in row.split("|")[2:-1]] == pytest.approx([0, 2 / 3, 4 / 3], abs=0.01)


def test_list_breaks_reads_a_saved_scene(empty_scene, tmp_path, capsys):
    """scripts/list_breaks.py: one row per break with its time, place, mode and the bonds left."""
    breaks = load_script("list_breaks")
    O.bodies.append([scene.disc((0, 0), R, material(bondTensileStrength=1e4), fixed=True),
                     scene.disc((0, 2 * R), R, material(bondTensileStrength=1e4))])
    O.engines = scene.engines(gravity=(0, 0, 0))
    bonding.bond_within_gap(1e-9)
    when = pull_until_broken(1)
    O.save(str(tmp_path / "scene.yade.bz2"))
    O.reset()
    breaks.main(str(tmp_path / "scene.yade.bz2"))
    row = [c.strip() for c in capsys.readouterr().out.splitlines()[3].split("|")[1:-1]]
    assert float(row[0]) == pytest.approx(when, rel=1e-3) and when > 0
    assert float(row[1]) == pytest.approx(0, abs=1e-4) and float(row[2]) == pytest.approx(R, rel=0.05)
    assert row[3:] == ["tension", "0, 1", "0, 0"]


def test_packing_overlaps_reports_the_discs_as_bonded(empty_scene, tmp_path):
    """scripts/packing_overlaps.py: overlaps from the ParaView series' reference positions (as
    bonded), not the discs' current ones nor the last equilibrium's."""
    overlaps = load_script("packing_overlaps")
    ids = scene.add_discs([(0, 0, R), (2 * R, 0, R), (4 * R, 0, R)], material())
    reference = [(0, 0, 0), (1.98 * R, 0, 0), (4 * R, 0, 0)]  # as bonded: the first pair overlapped by 0.02 R
    save_bonded_run(tmp_path, ids, reference, equilibrium=[(0, 0, 0), (2 * R, 0, 0), (4 * R, 0, 0)])
    line = overlaps.report(str(tmp_path))
    assert "3 discs, 1 overlapping pairs" in line and f"largest {0.02 * R:.2g} m (discs {ids[0]} and {ids[1]})" in line
    assert f"disc area {3 * math.pi * R * R:.6f} m2" in line


def test_onset_failure_names_the_overall_surface_beside_two():
    """scripts/onset_failure.py's φ cell: the overall surface beside a split, not beside one
    surface (it is that surface), nor for a summary older than ``phi_overall_deg``."""
    onset = load_script("onset_failure")
    assert onset.phi_text({"phi_deg": [1.9, 12.3], "phi_overall_deg": 15.0}) == "1.9, 12.3 (overall 15.0)"
    assert onset.phi_text({"phi_deg": [14.7], "phi_overall_deg": 14.7}) == "14.7"
    assert onset.phi_text({"phi_deg": [2.3, 44.5]}) == "2.3, 44.5" and onset.phi_text({"phi_deg": []}) == "-"
