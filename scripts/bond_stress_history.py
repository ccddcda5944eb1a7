"""Peak bond stresses at every stage of a tilting-table run, from its ParaView series.

    python3 scripts/bond_stress_history.py results/tilting_table/ideal_safety08 [30,40,50]

For each snapshot (one at the start tilt, one per stage end, one after the post-failure run)
prints the tilt of the stage it ends, the intact and broken bonds, and the three largest bond
tensile stresses sigma_max and the largest shear stress tau of the intact bonds [kPa]: how close
the rock is to its first crack, which is what a calibration of the bond strength moves. Given
stresses [kPa] (comma-separated), also how many intact bonds are above each: a few outliers
crack first, but a slope fails when many bonds crack.
"""
import json
import os
import sys
import xml.etree.ElementTree as ET
from typing import Optional, Sequence

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader


def snapshots(folder: str, kind: str = "bonds") -> list[tuple[float, str]]:
    """(simulated time, .vtu path) of the ``kind`` (bonds, discs) series in ``folder``/paraview."""
    series = os.path.join(folder, "paraview")
    root = ET.parse(os.path.join(series, f"{kind}.pvd")).getroot()
    return [(float(d.get("timestep")), os.path.join(series, d.get("file"))) for d in root.iter("DataSet")]


def run_record(folder: str) -> dict:
    """The run's summary.json or, while it runs, its checkpoint.json ({} if neither)."""
    for name in ("summary.json", "checkpoint.json"):
        path = os.path.join(folder, name)
        if os.path.exists(path):
            with open(path) as f:
                return json.load(f)
    return {}


def stage_tilts(folder: str) -> list[tuple[float, float]]:
    """(end time, tilt) of the run's stages."""
    return [(s["time"], s["tilt"]) for s in run_record(folder).get("stages", [])]


def stage_tilt(time: float, stages: list[tuple[float, float]]) -> Optional[float]:
    """The tilt of the stage (of the run's ``stage_tilts``) that ends at ``time``, None if none does."""
    return next((t for end, t in stages if abs(end - time) < 1e-9), None)


def snapshot_label(time: float, stages: list[tuple[float, float]]) -> str:
    """What the snapshot written at ``time`` shows, given the run's ``stage_tilts``: the tilt of
    the stage it ends, "start" (the slope at the start tilt, before its first stage ran) or
    "after failure"."""
    tilt = stage_tilt(time, stages)
    if tilt is not None:
        return f"{tilt:g}"
    return "start" if stages and time < stages[0][0] else "after failure"


def read_grid(path: str):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def cell_arrays(grid) -> dict[str, np.ndarray]:
    cells = grid.GetCellData()
    return {cells.GetArrayName(i): vtk_to_numpy(cells.GetArray(i)) for i in range(cells.GetNumberOfArrays())}


def bond_pairs(grid) -> np.ndarray:
    """The two disc (point) indices of each bond line of a bonds .vtu, one row per bond."""
    return vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 2)


def bond_arrays(path: str) -> dict[str, np.ndarray]:
    return cell_arrays(read_grid(path))


def main(folder: str, above: Sequence[float] = ()) -> None:
    stages = stage_tilts(folder)
    print("| time (s) | tilt (°) | intact | broken tension / shear | largest σ (kPa) | largest τ (kPa) |"
          + "".join(f" σ > {a:g} kPa |" for a in above))
    print("|---|---|---|---|---|---|" + "---|" * len(above))
    for time, path in snapshots(folder):
        tilt = snapshot_label(time, stages)
        bonds = bond_arrays(path)
        intact = bonds["state"] == 1
        stresses = bonds["sigma_max"][intact]
        sigma = np.sort(stresses)[::-1][:3] / 1e3
        tau = bonds["tau"][intact].max() / 1e3 if intact.any() else 0.0
        print(f"| {time:.3f} | {tilt} | {intact.sum()} | {(bonds['state'] == 2).sum()} / {(bonds['state'] == 3).sum()} | "
              f"{', '.join(f'{s:.1f}' for s in sigma)} | {tau:.1f} |"
              + "".join(f" {(stresses > 1e3 * a).sum()} |" for a in above))


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    main(sys.argv[1], [float(a) for a in sys.argv[2].split(",")] if len(sys.argv) == 3 else ())
