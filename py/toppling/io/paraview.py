"""ParaView time series of a run: ``discs.pvd``, ``bonds.pvd``, ``cracks.pvd``, ``joints.pvd`` + ``.vtu`` files.

The ``.vtu`` files are written by VTK's XML writer; each ``.pvd`` is the small XML index
ParaView reads a time series from (VTK has no writer for it), rewritten at every snapshot so
that a run stopped early can still be opened.

* discs: points with radius, displacement (from the positions when the series started),
  velocity, block id, ``fixed`` 1 where a boundary condition prescribes the disc's motion
  (a non-dynamic disc, or x or y blocked: the table's fixed layer, platens) (Glyph with the
  radius as scale to see discs);
* bonds: lines between the discs of each intact bond, ``sigma_max`` and ``tau`` [Pa];
* cracks: one point per broken bond, where and when it broke (the law's break records), with
  ``mode`` (2 tension, 3 shear), ``time`` [s], ``normal`` (the bond's axis) and ``size`` (its
  width across that axis, the crack's length) [m]: a broken bond is a crack where it broke, not
  a line between discs that have since parted;
* joints: each smooth-joint contact as a segment of the joint's trace through its contact point
  (along the joint, as wide as the contact), with its ``set``, normal and shear force [N] and
  accumulated slip [m].
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

from toppling.build import bonding, boundary, engines, joints

KINDS = ("discs", "bonds", "cracks", "joints")


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
        """Write the ``.vtu`` files of this moment (one per kind) and update the ``.pvd`` indexes."""
        n = len(self.times)
        pos = np.array([tuple(O.bodies[i].state.pos) for i in self.ids])
        grids = {"discs": self._discs(pos), "bonds": self._bonds(pos), "cracks": self._cracks(), "joints": self._joints()}
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
            "fixed": [int(boundary.is_held(b)) for b in bodies],
        }, {})

    def _bonds(self, pos: np.ndarray):
        cells, sigma, tau = [], [], []
        for I in O.interactions:
            if I.isReal and bonding.is_bond(I.phys):
                cells.append((self.index[I.id1], self.index[I.id2]))
                ours = isinstance(I.phys, ParallelBondPhys)  # JCFpm keeps no bond stresses
                sigma.append(I.phys.bondSigmaMax if ours else float("nan"))
                tau.append(I.phys.bondTauMax if ours else float("nan"))
        return _grid(pos, cells, VTK_LINE, {}, {"sigma_max": sigma, "tau": tau})

    @staticmethod
    def _cracks():
        law = engines.break_record()
        points = np.array([tuple(p) for p in law.breakPosition]).reshape(-1, 3)
        return _grid(points, [(k,) for k in range(len(points))], VTK_VERTEX, {}, {
            "mode": list(law.breakMode), "time": list(law.breakTime),
            "normal": np.array([tuple(v) for v in law.breakNormal]).reshape(-1, 3), "size": list(law.breakSize)})

    @staticmethod
    def _joints():
        ends, data = [], {"set": [], "normal_force": [], "shear_force": [], "slip": []}
        for I in O.interactions:
            if I.isReal and isinstance(I.phys, SmoothJointPhys):
                half = min(O.bodies[I.id1].shape.radius, O.bodies[I.id2].shape.radius)  # the contact's half-width
                centre = tuple(I.geom.contactPoint)
                ends += [(*end, centre[2]) for end in joints.trace(centre, tuple(I.phys.jointNormal), half)]
                data["set"].append(I.phys.jointSet)
                data["normal_force"].append(I.phys.jointNormalForce)
                data["shear_force"].append(I.phys.jointShearForce)
                data["slip"].append(I.phys.slip)
        return _grid(np.array(ends).reshape(-1, 3), [(2 * k, 2 * k + 1) for k in range(len(ends) // 2)], VTK_LINE, {},
                     data)

    def _write_index(self, kind: str) -> None:
        root = ET.Element("VTKFile", type="Collection", version="0.1", byte_order="LittleEndian")
        collection = ET.SubElement(root, "Collection")
        for n, t in enumerate(self.times):
            ET.SubElement(collection, "DataSet", timestep=repr(t), group="", part="0", file=f"{kind}_{n:05d}.vtu")
        ET.ElementTree(root).write(os.path.join(self.folder, f"{kind}.pvd"), xml_declaration=True)
