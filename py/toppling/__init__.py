"""toppling: block-flexural toppling of jointed rock slopes with YADE.

The package by role:

* :mod:`toppling.build`: discs, engines, packing, bonding, joints, boundary, column layouts
* :mod:`toppling.load`: tilting (gravity rotation, ramps, stages)
* :mod:`toppling.run`: steps, staged tilting runs, checkpoints that resume, progress, monitoring points, sweeps on Dask
* :mod:`toppling.analyse`: failure points and surfaces, zones, S/H and T/H, statistics over runs
* :mod:`toppling.io`: summary.json, plots, ParaView series, reading a run folder back
* :mod:`toppling.models`: parametrised scenes (tilting table, equivalent slope, block on an incline, specimen)
* :mod:`toppling.lem`: limit equilibrium (Goodman and Bray, Aydan and Kawamoto), plain Python

The names below are re-exported here, loaded on first use (so that ``toppling.analyse`` and
``toppling.io.output`` stay usable from a plain Python without YADE). The C++ classes
(``ParallelBondMat``, ``Law2_ScGeom_ParallelBondPhys_ParallelBond``, ...) are ordinary YADE
classes, imported with ``from yade import *``.
"""
import importlib

_API = {
    "disc": "build.discs", "add_discs": "build.discs", "engines": "build.engines", "broken_bonds": "build.engines",
    "pack_polygon": "build.packing", "pack_predicate": "build.packing", "shrink_overlaps": "build.packing", "region": "build.geometry", "bond_within_gap": "build.bonding",
    "install_joints": "build.joints", "fix": "build.boundary", "near": "build.boundary",
    "ColumnLayout": "build.columns", "set_tilt": "load.tilting", "run_steps": "run.steps",
    "run_checked": "run.steps", "Checkpoint": "run.checkpoint", "Progress": "run.progress",
    "write_summary": "io.output", "read_run": "io.reader", "ParaViewSeries": "io.paraview",
}
__all__ = sorted(_API)


def __getattr__(name: str):
    if name not in _API:
        raise AttributeError(f"module 'toppling' has no attribute {name!r}")
    return getattr(importlib.import_module(f"toppling.{_API[name]}"), name)
