"""Where the Ihlara cliff's packing is loose (docs/cases/ihlara.md): the intact cliff's discs for
each seed, the solid fraction of a square window (``cell`` m, 1.75 m by default: half a column)
slid over the rock by a seventh of its side, each disc counted in the window that holds its centre.
Windows stay Rmax inside the packing's walls. Prints the loosest window of the whole rock and the
loosest of column 1 (the front column) in its ignimbrite and at its foot (the windows across the
bedding), and the largest empty circle (the most room a disc would find).

    ./yade -x -n -j1 calibration/ihlara/voids.py [seeds, default 1 2 3 4 5] [cell=1.75] [rmin=R rmax=R]

``rmin``, ``rmax`` [m]: the packing's radii, Table 5-12's by default (calibration/ihlara/finer.table's:
rmin=0.10 rmax=0.1667).
"""
import sys
from types import SimpleNamespace

import numpy as np
from scipy.spatial import cKDTree

from examples import params
from toppling.models import layered_cliff, tilting_table

def windows(discs: np.ndarray, cliff, cell: float) -> list[tuple[float, float, float]]:
    """(left, bottom, solid fraction) of every ``cell``-wide window, slid by a seventh of it, that
    stays ``rmax`` inside the rock's walls."""
    x, y, area = discs[:, 0], discs[:, 1], np.pi * discs[:, 2] ** 2
    margin, found, stride = cliff.rmax, [], cell / 7
    for bottom in np.arange(-cliff.foundation.top + margin, cliff.height - margin - cell + 1e-9, stride):
        right = (cliff.face_x if bottom + cell > -margin else cliff.width) - margin
        row = (y >= bottom) & (y < bottom + cell)
        for left in np.arange(margin, right - cell + 1e-9, stride):
            inside = row & (x >= left) & (x < left + cell)
            found.append((left, bottom, area[inside].sum() / cell**2))
    return found


def largest_hole(discs: np.ndarray, box: tuple[float, float, float, float]) -> tuple[float, float, float]:
    """(x, y, radius) of the largest empty circle centred in ``box`` (x0, x1, y0, y1), on a 2 cm grid:
    the most room a disc would find between its neighbours."""
    gx, gy = np.meshgrid(np.arange(box[0], box[1], 0.02), np.arange(box[2], box[3], 0.02))
    points = np.column_stack([gx.ravel(), gy.ravel()])
    near, index = cKDTree(discs[:, :2]).query(points, k=8)
    room = (near - discs[index, 2]).min(axis=1)
    best = int(room.argmax())
    return points[best][0], points[best][1], room[best]


def column_1(w: tuple[float, float, float], cliff) -> bool:
    return w[0] >= cliff.face_x - cliff.column_width - 1e-9 and w[1] >= -cliff.column_width


def report(seed: int, cell: float, radii: dict[str, float]) -> None:
    """The seed's packing (``radii``: rmin, rmax over Table 5-12's): its loosest windows and
    largest empty circles, printed."""
    def show(label: str, w: tuple[float, float, float]) -> str:
        return f"{label} x {w[0]:.2f}-{w[0] + cell:.2f} m, y {w[1]:+.2f}-{w[1] + cell:+.2f} m: {w[2]:.3f}"

    cliff = layered_cliff.ihlara_from_params(
        SimpleNamespace(**{**params.IHLARA, **radii, "case": "intact", "seed": seed}), params)
    discs = np.array(tilting_table.packed_discs(cliff.section(), cliff.rmin, cliff.rmax, cliff.porosity, seed, False))
    found = windows(discs, cliff, cell)
    fractions = np.array([w[2] for w in found])
    print(f"seed {seed}: {len(discs)} discs, {len(found)} windows of {cell} m: solid fraction median "
          f"{np.median(fractions):.3f}, 1st percentile {np.percentile(fractions, 1):.3f}")
    print("  " + show("loosest:", min(found, key=lambda w: w[2])))
    mine = [w for w in found if column_1(w, cliff)]
    top = cliff.layers[0].top
    print("  " + show("column 1's loosest in the ignimbrite:", min((w for w in mine if 0 <= w[1] <= top - cell),
                                                                   key=lambda w: w[2])))
    print("  " + show("column 1's loosest at its foot:", min((w for w in mine if w[1] < 0 < w[1] + cell),
                                                              key=lambda w: w[2])))
    m = cliff.rmax
    anywhere = largest_hole(discs, (m, cliff.face_x - m, -cliff.foundation.top + m, cliff.height - m))
    in_column = largest_hole(discs, (cliff.face_x - cliff.column_width, cliff.face_x - m, -cliff.column_width,
                                     cliff.height - m))
    print(f"  largest empty circle behind the face: r {anywhere[2]:.3f} m at ({anywhere[0]:.2f}, {anywhere[1]:+.2f}); "
          f"in column 1: r {in_column[2]:.3f} m at ({in_column[0]:.2f}, {in_column[1]:+.2f}) (Rmin {cliff.rmin} m)",
          flush=True)


if __name__ == "__main__":
    args = sys.argv[1:]
    options = {k: float(v) for k, _, v in (a.partition("=") for a in args if "=" in a)}
    cell = options.pop("cell", 1.75)
    for seed in [int(a) for a in args if a.isdigit()] or [1, 2, 3, 4, 5]:
        report(seed, cell, options)
