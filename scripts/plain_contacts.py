"""Plain disc contacts of a saved scene: pairs that were never bonded and are not joints.

    ./yade -x -n scripts/plain_contacts.py results/tilting_table/random_every_cut_fail2/checkpoint.yade.bz2

In rock packed and bonded whole, a contact that was never bonded formed after the joints were
installed: a piece that moved by a disc spacing met rock as discs. Across a joint that is the
particle interlocking smooth joints are there to remove (`joint_pieces`, docs/tilting_table.md).
Prints the counts of rock interactions by bond state and every plain contact carrying more than
0.1 N: the two discs, their pieces (JointSystem.blockOfBody) and their displacements.
"""
import sys
from collections import Counter

from yade import O
from yade.wrapper import ParallelBondPhys

from toppling import bonding, joints, scene

STATES = {0: "never bonded", 1: "intact", **{code: f"broken in {mode}" for code, mode in scene.BREAK_MODES.items()}}


def xy(v) -> str:
    return f"({v[0] * 1e3:.1f}, {v[1] * 1e3:.1f})"


def main(path: str) -> None:
    O.load(path)
    rock = [I for I in O.interactions if I.isReal and isinstance(I.phys, ParallelBondPhys)]
    counts = Counter(I.phys.bondState for I in rock)
    print(f"{path} (t = {O.time:.4g} s): " + ", ".join(f"{n} {STATES[s]}" for s, n in sorted(counts.items())))
    plain = sorted((I for I in rock if I.phys.bondState == 0 and I.phys.normalForce.norm() > 0.1),
                   key=lambda I: -I.phys.normalForce.norm())
    pieces = joints.rock_functor().joints.blockOfBody
    print(f"{len(plain)} never-bonded contacts carry more than 0.1 N")
    print("| force (N) | discs | positions (mm) | pieces | displacements (mm) | intact bonds |")
    print("|---|---|---|---|---|---|")
    for I in plain:
        a, b = O.bodies[I.id1], O.bodies[I.id2]
        print(f"| {I.phys.normalForce.norm():.2f} | {a.id}, {b.id} | {xy(a.state.pos)}, {xy(b.state.pos)} | "
              f"{pieces[a.id]}, {pieces[b.id]} | {xy(a.state.displ())}, {xy(b.state.displ())} | "
              f"{bonding.intact_bonds(a.id)}, {bonding.intact_bonds(b.id)} |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
