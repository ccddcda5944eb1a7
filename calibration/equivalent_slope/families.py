"""Write examples/equivalent_slope/families.table: the four parametric families of thesis §5.3.3
on the base model (examples/params.py's EQUIVALENT_SLOPE), each case on packing seeds 1-3 (the
same packings in every case: differences between cases are paired).

    source scripts/env.sh; /usr/bin/python3 calibration/equivalent_slope/families.py

Our reading of the cases (the thesis' drawings are missing):
* Table 5-7, (N2-N1): the base joints of columns N1 and N2 = N1 + 1 as one joint crossing both
  (``merged_pair`` N1); case I is (17-16), case XVI (2-1).
* Table 5-8: I one base joint along the whole table plane (the plane through the toe normal to the
  main joints, where the thesis' φ of 0° puts its failure surface); II none; III one crossing
  columns 1-3; IV each base joint (columns 1, 3, ...) extended across the next column (1-2, 3-4,
  ...); V the base set and a copy of it 0.13 m up the columns. III and IV lie on the base set's
  plane (``base_plane_deg``) at their centres, as merged pairs do.
* Table 5-9: main-joint spacing 0.0235 m on discs half the base model's (R 0.75-1.75 mm: the
  columns keep their width / Rmax of 13.4) and 0.094 m on the base model's.
* Table 5-10: main-joint friction 0 ... 0.6; case 1, the thesis' base model, at its 0.12 (ours is
  calibrated at 0.20).
"""
import math
import os

from examples import params
from toppling.models.equivalent_slope import SlopeShape

SEEDS = (1, 2, 3)
TABLE = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "equivalent_slope", "families.table")


def on_plane(spans: list[tuple[int, int]], offset: float = 0.0) -> str:
    """Base joints across the columns of each span, on the base set's plane at the span's centre
    (``offset`` [m] higher), where it crosses the columns below their tops; as base_joints text."""
    layout = SlopeShape(**params.EQUIVALENT_SLOPE_SHAPE).outline().layout()
    rise = math.tan(math.radians(params.EQUIVALENT_SLOPE["base_plane_deg"]))
    items = []
    for first, last in spans:
        height = rise * 0.5 * (first - 1 + last) * layout.width + offset
        if height < min(layout.heights[first - 1:last]):
            items.append(f"{first}-{last}@{height:.4f}")
    return "'" + ";".join(items) + "'"


BLOCKY = [(k, k) for k in range(1, 23, 2)]  # the base model's blocky columns


def cases() -> list[tuple[str, dict]]:
    found = [("base", {})]
    roman = "I II III IV V VI VII VIII IX X XI XII XIII XIV XV XVI".split()
    found += [(f"t57_{r}_{17 - k}-{16 - k}", {"merged_pair": 16 - k}) for k, r in enumerate(roman)]
    found += [("t58_I_continuous", {"base_joints": "'1-22'"}), ("t58_II_none", {"base_joints": "'none'"}),
              ("t58_III_toe", {"base_joints": on_plane([(1, 3)])}),
              ("t58_IV_pairs", {"base_joints": on_plane([(k, k + 1) for k, _ in BLOCKY])}),
              ("t58_V_second_set", {"base_joints": on_plane(BLOCKY)[:-1] + ";" + on_plane(BLOCKY, 0.13)[1:]})]
    # half the spacing on discs half the size: the columns keep their width / Rmax (13.4)
    fine = {"rmin": params.EQUIVALENT_SLOPE["rmin"] / 2, "rmax": params.EQUIVALENT_SLOPE["rmax"] / 2}
    found += [("t59_I_0.0235", {"spacing": 0.0235, **fine}), ("t59_II_0.094", {"spacing": 0.094})]
    found += [(f"t510_{case}_mu{mu}", {"main_joint_friction": mu})
              for case, mu in ((1, 0.12), (2, 0.0), (3, 0.176), (4, 0.26), (5, 0.36), (6, 0.46), (7, 0.56), (8, 0.58), (9, 0.6))]
    return found


SETTLED = "results/equivalent_slope/settled"  # a case settles its packing once (tilt_run.settled_store)


def main() -> None:
    base = params.EQUIVALENT_SLOPE
    columns = ["description", "seed", "spacing", "base_joints", "merged_pair", "main_joint_friction", "rmin", "rmax", "out",
               "settled_dir"]
    rows = []
    for seed in SEEDS:  # seed by seed: a sweep stopped part way has every case on the first packings
        for name, change in cases():
            row = {"description": f"{name}_s{seed}", "seed": seed, "spacing": base["spacing"],
                   "base_joints": repr(base["base_joints"]), "merged_pair": base["merged_pair"],
                   "main_joint_friction": base["main_joint_friction"], "rmin": base["rmin"], "rmax": base["rmax"],
                   "out": f"'results/equivalent_slope/families/{name}_s{seed}'", "settled_dir": f"'{SETTLED}'",
                   **change}
            rows.append([str(row[c]) for c in columns])
    width = [max(len(c), *(len(r[k]) for r in rows)) for k, c in enumerate(columns)]
    with open(TABLE, "w") as f:
        f.write("# Written by calibration/equivalent_slope/families.py (the cases and how we read them); run with\n"
                "#   ./yade-batch -j2 --job-threads 1 --log 'results/equivalent_slope/families/@.log' "
                "examples/equivalent_slope/families.table examples/equivalent_slope/run.py\n")
        for line in [columns] + rows:
            f.write(" ".join(cell.ljust(w) for cell, w in zip(line, width)).rstrip() + "\n")
    print(f"{len(rows)} lines ({len(rows) // len(SEEDS)} cases x {len(SEEDS)} seeds) in {os.path.normpath(TABLE)}")


if __name__ == "__main__":
    main()
