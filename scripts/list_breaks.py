"""The bond breaks of a saved scene: when, where and how each bond broke, in the order they did.

    ./yade -x -n scripts/list_breaks.py results/tilting_table/ideal_bond85_safety08/checkpoint.yade.bz2 [--before]

Prints one row per break: simulated time, bond centre, mode, the two discs and the intact
bonds each still has (with ``--before`` first the intact bonds each had just before the break;
toppling.bonding.rock_breaks tells cracks from breaks that freed a disc). A break in the first
steps, before gravity has moved anything, is a bond that the packing's overlap pushed apart; a
disc left with fewer than two bonds is not rock any more (toppling.bonding.rock).
"""
import sys

from yade import O

from toppling import bonding, scene


def main(path: str, before: bool = False) -> None:
    O.load(path)
    law = scene.bond_law()
    print(f"{len(law.breakMode)} breaks in {path} (t = {O.time:.4g} s)")
    columns = ["t (s)", "x (m)", "y (m)", "mode", "discs"] + ["bonds before"] * before + ["intact bonds left"]
    print("| " + " | ".join(columns) + " |")
    print("|" + "---|" * len(columns))
    counts = bonding.bonds_before_breaks() if before else [None] * len(law.breakMode)
    for t, p, mode, a, b, pair in zip(law.breakTime, law.breakPosition, law.breakMode, law.breakId1, law.breakId2,
                                      counts):
        had = f"{pair[0]}, {pair[1]} | " if before else ""
        print(f"| {t:.4g} | {p[0]:.4f} | {p[1]:.4f} | {scene.BREAK_MODES[mode]} | {a}, {b} | {had}"
              f"{bonding.intact_bonds(a)}, {bonding.intact_bonds(b)} |")


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if a != "--before"]
    if len(args) != 1:
        sys.exit(__doc__)
    main(args[0], "--before" in sys.argv[1:])
