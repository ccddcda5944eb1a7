"""ParaView time series of a run: ``discs.pvd``, ``bonds.pvd``, ``joints.pvd`` + ``.vtu`` files.

The ``.vtu`` files are written by VTK's XML writer; each ``.pvd`` is the small XML index
ParaView reads a time series from (VTK has no writer for it), rewritten at every snapshot so
that a run stopped early can still be opened.

* discs: points with radius, displacement (from the positions when the series started),
  velocity, block id, ``fixed`` 1 where a boundary condition prescribes the disc's motion
  (a non-dynamic disc, or x or y blocked: the table's fixed layer, platens) (Glyph with the
  radius as scale to see discs);
* bonds: lines between bonded discs, ``state`` 1 intact, 2 broken in tension, 3 broken in
  shear (broken bonds from the law's break records), ``sigma_max`` and ``tau`` [Pa];
* joints: lines between the discs of each smooth-joint contact with joint set, normal and
  shear force [N] and accumulated slip [m].
"""
from __future__ import annotations

import os
import xml.etree.ElementTree as ET

from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_LINE, VTK_VERTEX, vtkUnstructuredGrid
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
import numpy as np
from yade import O
from yade.wrapper import ParallelBondPhys, SmoothJointPhys, Sphere

from toppling.build import engines

KINDS = ("discs", "bonds", "joints")


def _grid(points: np.ndarray, cells: list[tuple[int, ...]], cell_type: int, point_data: dict, cell_data: dict):
    grid = vtkUnstructuredGrid()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=float).reshape(-1, 3), deep=True))
    grid.SetPoints(vtk_points)
    grid.Allocate(len(cells))
    for cell in cells:
        grid.InsertNextCell(cell_type, len(cell), cell)
    for target, data in ((grid.GetPointData(), point_data), (grid.GetCellData(), cell_data)):
        for name, values in data.items():
            array = numpy_to_vtk(np.ascontiguousarray(values, dtype=float), deep=True)
            array.SetName(name)
            target.AddArray(array)
    return grid


def _write(grid, path: str) -> None:
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetFileName(path)
    writer.SetInputData(grid)
    writer.SetDataModeToBinary()
    if writer.Write() != 1:
        raise OSError(f"VTK could not write {path}")


class ParaViewSeries:
    """Snapshots of the current scene into ``<folder>``; displacements from now on, or, when
    resuming, from ``state`` (what :meth:`state` returned then)."""

    def __init__(self, folder: str, block_of_body=None, state: dict | None = None):
        os.makedirs(folder, exist_ok=True)
        self.folder = folder
        self.block_of_body = list(block_of_body or [])
        if state:
            self.ids, self.reference, self.times = state["ids"], np.array(state["reference"]), state["times"]
        else:
            self.ids = [b.id for b in O.bodies if b is not None and isinstance(b.shape, Sphere)]
            self.reference = np.array([tuple(O.bodies[i].state.pos) for i in self.ids])
            self.times = []
        self.index = {i: k for k, i in enumerate(self.ids)}

    def state(self) -> dict:
        """What a resumed run needs to continue this series (JSON-serialisable)."""
        return {"ids": self.ids, "reference": self.reference.tolist(), "times": self.times}

    def snapshot(self) -> list[str]:
        """Write the three ``.vtu`` files of this moment and update the ``.pvd`` indexes."""
        n = len(self.times)
        pos = np.array([tuple(O.bodies[i].state.pos) for i in self.ids])
        grids = {"discs": self._discs(pos), "bonds": self._bonds(pos), "joints": self._joints(pos)}
        paths = []
        for kind, grid in grids.items():
            paths.append(os.path.join(self.folder, f"{kind}_{n:05d}.vtu"))
            _write(grid, paths[-1])
        self.times.append(O.time)
        for kind in KINDS:
            self._write_index(kind)
        return paths

    def _discs(self, pos: np.ndarray):
        bodies = [O.bodies[i] for i in self.ids]
        block = [self.block_of_body[i] if i < len(self.block_of_body) else -1 for i in self.ids]
        return _grid(pos, [(k,) for k in range(len(pos))], VTK_VERTEX, {
            "radius": [b.shape.radius for b in bodies],
            "displacement": pos - self.reference,
            "velocity": np.array([tuple(b.state.vel) for b in bodies]),
            "block": block,
            "fixed": [int(not b.dynamic or bool(set(b.state.blockedDOFs) & {"x", "y"})) for b in bodies],
        }, {})

    def _bonds(self, pos: np.ndarray):
        cells, state, sigma, tau = [], [], [], []
        for I in O.interactions:
            if I.isReal and isinstance(I.phys, ParallelBondPhys) and I.phys.bondState == 1:
                cells.append((self.index[I.id1], self.index[I.id2]))
                state.append(1)
                sigma.append(I.phys.bondSigmaMax)
                tau.append(I.phys.bondTauMax)
        law = engines.bond_law()
        for i, j, mode in zip(law.breakId1, law.breakId2, law.breakMode):
            cells.append((self.index[i], self.index[j]))
            state.append(mode)
            sigma.append(0.0)
            tau.append(0.0)
        return _grid(pos, cells, VTK_LINE, {}, {"state": state, "sigma_max": sigma, "tau": tau})

    def _joints(self, pos: np.ndarray):
        cells, data = [], {"set": [], "normal_force": [], "shear_force": [], "slip": []}
        for I in O.interactions:
            if I.isReal and isinstance(I.phys, SmoothJointPhys):
                cells.append((self.index[I.id1], self.index[I.id2]))
                data["set"].append(I.phys.jointSet)
                data["normal_force"].append(I.phys.jointNormalForce)
                data["shear_force"].append(I.phys.jointShearForce)
                data["slip"].append(I.phys.slip)
        return _grid(pos, cells, VTK_LINE, {}, data)

    def _write_index(self, kind: str) -> None:
        root = ET.Element("VTKFile", type="Collection", version="0.1", byte_order="LittleEndian")
        collection = ET.SubElement(root, "Collection")
        for n, t in enumerate(self.times):
            ET.SubElement(collection, "DataSet", timestep=repr(t), group="", part="0", file=f"{kind}_{n:05d}.vtu")
        ET.ElementTree(root).write(os.path.join(self.folder, f"{kind}.pvd"), xml_declaration=True)
