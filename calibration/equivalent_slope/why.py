"""Why a family case differs from the base model: the two runs on the same packing, column by
column (each column's zone and its cracks, tensile / shear, in the rock above the table plane; a
standing run's column tops' displacement), so that a disagreement with the thesis is told by which
columns, which bonds and which joint made it.

    source scripts/env.sh; /usr/bin/python3 calibration/equivalent_slope/why.py CASE_RUN [BASE_RUN]
e.g. results/equivalent_slope/families/t57_V_13-12_s1 (the base run: base_s<seed> beside it).
"""
import glob
import json
import os
import sys
from collections import Counter

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

from toppling.analyse.seeds import fmt
from toppling.build.columns import ColumnLayout
from toppling.io.reader import summary_of

MODES = {2: "tensile", 3: "shear"}  # BREAK_MODES of the parallel-bond law


def cracks_by_column(run: str, layout: ColumnLayout) -> dict[int, Counter]:
    """The run's cracks (its last ParaView snapshot) by column (0: the foundation) and mode."""
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(sorted(glob.glob(os.path.join(run, "paraview", "cracks_*.vtu")))[-1])
    reader.Update()
    grid = reader.GetOutput()
    if grid.GetNumberOfPoints() == 0:
        return {}
    points, modes = vtk_to_numpy(grid.GetPoints().GetData()), vtk_to_numpy(grid.GetCellData().GetArray("mode"))  # a vertex per crack
    found: dict[int, Counter] = {}
    for (x, y, _), mode in zip(points, modes):
        column = layout.column_of(x) if y >= 0 else 0
        found.setdefault(column, Counter())[MODES.get(int(mode), str(mode))] += 1
    return found


def describe(run: str) -> tuple[dict, dict[int, Counter]]:
    """The run's summary and its cracks by column (its layout from the checkpoint's state)."""
    with open(os.path.join(run, "checkpoint.json")) as f:
        layout = ColumnLayout(**json.load(f)["layout"])
    return summary_of(run), cracks_by_column(run, layout)


def main(case: str, base: str) -> None:
    (mine, my_cracks), (theirs, their_cracks) = describe(case), describe(base)
    print(f"{os.path.basename(case)} beside {os.path.basename(base)}: failed {mine['failed']} / {theirs['failed']}, "
          f"φ {mine.get('phi_overall_deg')} / {theirs.get('phi_overall_deg')}\n")
    print("| column | zone | base's zone | cracks t / s | base's | top moved (mm) | base's |\n|---|---|---|---|---|---|---|")
    labels = list(mine.get("zones") or mine.get("top_displacement_mm") or theirs.get("zones") or {})  # A-1, B-2, ...
    for k, label in enumerate(labels, start=1):
        cells = []
        for s, cracks in ((mine, my_cracks), (theirs, their_cracks)):
            c = cracks.get(k, Counter())
            cells.append(((s.get("zones") or {}).get(label, "-"), f"{c['tensile']} / {c['shear']}",
                          (s.get("top_displacement_mm") or {}).get(label)))
        (zone, cracks, top), (base_zone, base_cracks, base_top) = cells
        if (zone, cracks) != (base_zone, base_cracks):
            print(f"| {label} | {zone} | {base_zone} | {cracks} | {base_cracks} | {fmt(top)} | {fmt(base_top)} |")
    foundation = my_cracks.get(0, Counter()), their_cracks.get(0, Counter())
    print(f"\nfoundation cracks t / s: {foundation[0]['tensile']} / {foundation[0]['shear']} "
          f"(base {foundation[1]['tensile']} / {foundation[1]['shear']})")


if __name__ == "__main__":
    case = sys.argv[1].rstrip("/")
    seed = case.rsplit("_s", 1)[1]
    main(case, sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(case), f"base_s{seed}"))
