"""calibration/equivalent_slope/why.py: a run's cracks counted by column from its ParaView snapshot."""
import numpy as np
from conftest import load_script
from vtkmodules.vtkCommonDataModel import VTK_VERTEX

from toppling.build.columns import ColumnLayout
from toppling.io import paraview

why = load_script("calibration/equivalent_slope/why.py")


def test_cracks_are_counted_by_column_and_mode_from_the_last_snapshot_and_the_foundations_apart(tmp_path):
    layout = ColumnLayout(toe_x=0.0, width=0.05, heights=[0.1, 0.2, 0.3])  # column k spans x in (-0.05 k, -0.05 (k - 1))
    (tmp_path / "paraview").mkdir()
    points = np.array([(-0.01, 0.02, 0), (-0.02, 0.05, 0), (-0.07, 0.1, 0), (-0.12, 0.2, 0), (-0.03, -0.01, 0)])
    modes = [2, 3, 3, 2, 3]  # tensile, shear
    for n, keep in ((0, 1), (1, len(points))):  # an earlier snapshot with fewer cracks
        grid = paraview._grid(points[:keep], [(k,) for k in range(keep)], VTK_VERTEX, {}, {"mode": modes[:keep]})
        paraview._write(grid, str(tmp_path / "paraview" / f"cracks_{n:05d}.vtu"))
    found = why.cracks_by_column(str(tmp_path), layout)
    assert {k: dict(c) for k, c in found.items()} == {1: {"tensile": 1, "shear": 1}, 2: {"shear": 1}, 3: {"tensile": 1},
                                                      0: {"shear": 1}}
