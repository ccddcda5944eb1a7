"""Where an equivalent-slope run cracked: per column, the bonds broken at its root (within 2 Rmax
of the table plane, where the base joints lie and the flexural columns meet the foundation) and
above it, by mode; a slope that slides on the table plane has sheared its flexural columns' roots.

    ./yade -x -n -j1 calibration/equivalent_slope/root_cracks.py results/equivalent_slope/RUN [...]
"""
import json
import os
import sys

from yade import O

from toppling.analyse import failure
from toppling.build import columns, engines


def main(outs: list[str]) -> None:
    for out in outs:
        with open(os.path.join(out, "checkpoint.json")) as f:
            state = json.load(f)
        O.load(os.path.join(out, "checkpoint.yade.bz2"))
        layout, rmax = columns.ColumnLayout(**state["layout"]), state["inputs"]["rmax"]
        law = engines.bond_law()
        counts: dict[int, dict[str, int]] = {}
        for (x, y, _), mode in zip(law.breakPosition, law.breakMode):
            k = layout.column_of(x)
            if k:
                where = "root" if abs(y) < 2 * rmax else "above"
                key = f"{where} {engines.BREAK_MODES[mode]}"
                counts.setdefault(k, {}).setdefault(key, 0)
                counts[k][key] += 1
        print(f"{os.path.basename(out.rstrip('/'))}: column: root tension / root shear / above tension / above shear "
              "(odd columns stand on a base joint, even ones are bonded to the foundation)")
        for k in sorted(counts):
            c = counts[k]
            print(f"  {failure.column_label(k)}: {c.get('root tension', 0)} / {c.get('root shear', 0)} / "
                  f"{c.get('above tension', 0)} / {c.get('above shear', 0)}")
        flexural = [counts.get(k, {}) for k in range(2, layout.count + 1, 2)]
        roots = sum(c.get("root shear", 0) + c.get("root tension", 0) for c in flexural)
        print(f"  flexural columns' roots: {roots} cracks, "
              f"{sum(c.get('root shear', 0) for c in flexural)} of them in shear")


if __name__ == "__main__":
    main(sys.argv[1:])
