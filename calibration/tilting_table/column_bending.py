"""How strong in bending is the tilting-table rock? One continuous column of it, tilted.

A column of the ideal (or random) tilting-table material, 5 cm wide and ``height`` tall, cut
from a packing as the example's columns are, its bottom discs fixed, is tilted by turning
gravity at ``rate`` deg/s until it breaks. Prints the tilt and height of the first broken bond
and the tilt at which the top has moved half the width (the column has broken and toppled; its
elastic bending is < 8 mm even at 90 deg), each with the tensile stress beam theory gives at the
base then, sigma = 3 gamma h^2 sin(a) / b - gamma h cos(a), to compare with the block material's
tensile strength (31.37 kPa, thesis §5.2.1): a continuous column stronger than the slope needs
stands when its neighbours fall.

    ./yade -x -n -j1 calibration/tilting_table/column_bending.py rmin rmax bond_tensile_strength [name=value ...]

Names: ``height`` [m] (0.3), ``rate`` [deg/s] (10), or any parameter of the tilting-table example
(``seed=2``, ``bond_gap=0.735e-3``, ``arrangement=random``, ...), at the example's default otherwise.
"""
import ast
import math
import sys
from types import SimpleNamespace

from yade import O

from examples import params
from toppling.build import engines, geometry, packing
from toppling.lem.flexural import base_tension
from toppling.load import tilting
from toppling.models import tilting_table
from toppling.run.steps import run_checked, run_steps


def build_column(slope: tilting_table.TiltingTable, width: float, height: float) -> list[int]:
    """The column's discs, bonded as the model's rock, bottom Rmax fixed; returns their ids."""
    margin = 2 * width  # pack wider and cut: the column's sides are cut through, as by joints
    outline = [(-margin, 0), (width + margin, 0), (width + margin, height), (-margin, height)]
    discs = packing.pack_polygon(geometry.region(outline), slope.rmin, slope.rmax, slope.porosity,
                                 seed=slope.seed).discs
    return slope.bonded_rock([d for d in discs if 0 <= d[0] <= width], ((-1, 0), (1, 0)))


def value(text: str):
    """A command-line value: a number, or the text (``random``)."""
    try:
        return ast.literal_eval(text)
    except (ValueError, SyntaxError):
        return text


def main() -> None:
    args = sys.argv[1:]
    if len(args) < 3 or not all("=" in a for a in args[3:]):
        raise SystemExit(__doc__)
    rmin, rmax, strength = (float(a) for a in args[:3])
    options = dict(a.split("=", 1) for a in args[3:])
    height, rate = float(options.pop("height", 0.3)), float(options.pop("rate", 10.0))
    if rate <= 0 or height <= 0:
        raise ValueError(f"height = {height} m, rate = {rate} deg/s are invalid: both must be > 0")
    case = SimpleNamespace(**{**params.TILTING_TABLE_IDEAL, "rmin": rmin, "rmax": rmax,
                              "bond_tensile_strength": strength, **{k: value(v) for k, v in options.items()}})
    slope = tilting_table.from_params(case, params)
    width = slope.outline.width
    ids = build_column(slope, width, height)
    top = max(ids, key=lambda i: O.bodies[i].state.pos[1])
    run_steps(int(0.2 / O.dt))  # settle under gravity on the level base
    gamma = sum(O.bodies[i].state.mass for i in ids) * engines.G / (width * height * slope.rock["thickness"])  # bulk [N/m3]
    reference = tuple(O.bodies[top].state.pos)
    law, tilt, first, broke, start = engines.bond_law(), 0.0, None, False, O.time
    while tilt < 90:
        run_checked(1e-3, f"the column at {tilt:.1f} deg")
        tilt = rate * (O.time - start)
        tilting.set_tilt(tilt)
        if first is None and len(law.breakMode):
            first = (tilt, engines.BREAK_MODES[law.breakMode[0]], law.breakPosition[0][1])
        broke = math.dist(tuple(O.bodies[top].state.pos)[:2], reference[:2]) > 0.5 * width
        if broke:  # bending alone moves it < 8 mm even at 90 deg
            break
    print(f"column {1e3 * width:g} x {1e3 * height:g} mm, {slope.arrangement} rock, bond tensile strength "
          f"{strength / 1e3:g} kPa, R {1e3 * rmin:g}-{1e3 * rmax:g} mm (seed {slope.seed}, bond gap "
          f"{1e3 * slope.bond_gap:g} mm), {len(ids)} discs, {rate:g} deg/s, unit weight {gamma / 1e3:.1f} kN/m3")
    if first:
        print(f"first bond broken ({first[1]}, {1e3 * first[2]:.1f} mm above the base) at {first[0]:.1f} deg: "
              f"beam tension at the base {base_tension(gamma, width, height, first[0]) / 1e3:.1f} kPa")
    if not broke:
        print(f"stood to {tilt:.1f} deg")
        return
    print(f"failed (top moved {1e3 * 0.5 * width:g} mm) at {tilt:.1f} deg: beam tension at the base "
          f"{base_tension(gamma, width, height, tilt) / 1e3:.1f} kPa "
          f"(block material: {params.BLOCK_TENSILE_STRENGTH / 1e3:.2f} kPa)")


main()
