"""The bond breaks of a saved scene: when, where and how each bond broke, in the order they did.

    ./yade -x -n scripts/list_breaks.py results/tilting_table/ideal_bond85_safety08/checkpoint.yade.bz2

Prints one row per break: simulated time, bond centre, mode, the two discs, the intact bonds
each had just before it (a disc with fewer than two was loose: toppling.bonding.rock_breaks) and
the intact bonds each still has. A break in the first steps, before gravity has moved anything, is a
bond that the packing's overlap pushed apart; a disc left with fewer than two bonds is not
rock any more (toppling.bonding.rock).
"""
import sys

from yade import O

from toppling import bonding, scene


def main(path: str) -> None:
    O.load(path)
    law = scene.bond_law()
    print(f"{len(law.breakMode)} breaks in {path} (t = {O.time:.4g} s)")
    print("| t (s) | x (m) | y (m) | mode | discs | bonds before | intact bonds left |")
    print("|---|---|---|---|---|---|---|")
    before = bonding.bonds_before_breaks()
    rows = zip(law.breakTime, law.breakPosition, law.breakMode, law.breakId1, law.breakId2, before)
    for t, p, mode, a, b, (before_a, before_b) in rows:
        print(f"| {t:.4g} | {p[0]:.4f} | {p[1]:.4f} | {scene.BREAK_MODES[mode]} | {a}, {b} | {before_a}, {before_b} | "
              f"{bonding.intact_bonds(a)}, {bonding.intact_bonds(b)} |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
