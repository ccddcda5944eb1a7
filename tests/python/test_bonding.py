"""toppling.build.bonding: which discs bonds hold together."""
from yade import O
from yade.wrapper import ParallelBondMat

from conftest import ROCK
from toppling.build import bonding, engines
from toppling.build.discs import add_discs


def test_the_largest_piece_is_what_intact_bonds_hold_together(empty_scene):
    """A chain of three touching discs, a touching pair apart from it, a lone disc: the chain is
    the largest piece; with the chain's middle bond broken the pair and the chain's two halves tie
    and the smallest id's piece wins."""
    r = 0.01
    ids = add_discs([(0, 0, r), (2 * r, 0, r), (4 * r, 0, r), (10 * r, 0, r), (12 * r, 0, r), (20 * r, 0, r)],
                    ParallelBondMat(**ROCK))
    O.engines = engines.engines()
    bonding.bond_within_gap(0.0)
    assert bonding.largest_piece(ids) == ids[:3]
    assert bonding.largest_piece(ids[::-1]) == ids[2::-1]  # in the order given
    O.interactions[ids[1], ids[2]].phys.bondState = 2  # broken in tension
    assert bonding.largest_piece(ids) == ids[:2]
    assert bonding.largest_piece(ids[3:] + ids[:2]) == ids[:2]  # the tie goes to the smallest id, whatever the order
