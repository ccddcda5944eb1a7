"""Install parallel bonds between discs closer than a gap, at any moment of a run."""
from __future__ import annotations

from collections import defaultdict
from typing import Iterable, Iterator, Optional, Sequence

from yade import O, utils
from yade.wrapper import Sphere

from toppling.build import packing
from toppling.build.engines import break_record, limit_timestep
from toppling.checks import require


def _sphere_ids(ids: Optional[Sequence[int]]) -> list[int]:
    bodies = O.bodies if ids is None else (O.bodies[i] for i in ids)
    return [b.id for b in bodies if b is not None and isinstance(b.shape, Sphere)]


def pairs_within_gap(gap: float, ids: Optional[Sequence[int]] = None) -> Iterator[tuple[int, int]]:
    """Pairs (i < j) of spheres whose surfaces are at most ``gap`` apart (overlapping pairs too)."""
    spheres = sorted(_sphere_ids(ids))  # index order = id order
    centres = [tuple(O.bodies[i].state.pos)[:2] for i in spheres]
    radii = [O.bodies[i].shape.radius for i in spheres]
    for i, j, _ in packing.pairs_within(centres, radii, gap):
        yield spheres[i], spheres[j]


def remove_floaters(gap: float = 0.0, min_neighbours: int = 2, ids: Optional[Sequence[int]] = None) -> list[int]:
    """Delete discs (among ``ids``) with fewer than ``min_neighbours`` others within ``gap`` [m].

    Such discs would be loose in the bonded rock (Potyondy & Cundall 2004 eliminate these
    "floaters"): a disc with no bond rattles in its pore and, on a joint, wedges the blocks
    apart; with one bond it swings about it. Returns the ids removed.
    """
    require("min_neighbours", min_neighbours, "[0, inf)")
    count = defaultdict(int)
    for i, j in pairs_within_gap(gap, ids):
        count[i] += 1
        count[j] += 1
    floaters = [i for i in _sphere_ids(ids) if count[i] < min_neighbours]
    for i in floaters:
        O.bodies.erase(i)
    return floaters


def bond_within_gap(gap: float = 0.0, ids: Optional[Sequence[int]] = None) -> int:
    """Bond every pair of discs (among ``ids``, default all) within ``gap`` [m].

    The bond is stress-free in the current configuration, so this may be called after the
    packing has settled (thesis §3.2). Already-bonded pairs are left alone. Returns the number
    of new bonds.
    """
    require("gap", gap, "[0, inf)")
    count = 0
    for i, j in pairs_within_gap(gap, ids):
        interaction = O.interactions[i, j] if O.interactions.has(i, j) else None
        if interaction is not None and not interaction.isReal:
            O.interactions.erase(i, j)
            interaction = None
        if interaction is None:
            interaction = utils.createInteraction(i, j)
        if interaction.phys.bondState != 1:
            interaction.phys.installBond(interaction.geom.penetrationDepth, interaction.geom.normal)
            count += 1
    limit_timestep()
    return count


def intact_bonds(body_id: int) -> int:
    """Number of intact bonds of a disc (parallel bonds, or JCFpm's cohesive contacts)."""
    return sum(1 for i in O.bodies[body_id].intrs() if is_bond(i.phys))


def is_bond(phys) -> bool:
    """Whether an interaction's physics is an intact bond: ours, or JCFpm's cohesive contact."""
    return getattr(phys, "bondState", 0) == 1 or getattr(phys, "isCohesive", False)


def rock(ids: Sequence[int], min_bonds: int = 2) -> list[int]:
    """The discs of ``ids`` held by at least ``min_bonds`` intact bonds: the rock, without the
    loose discs and pairs that rattle, roll or drop off (which must not count as rock moving)."""
    return [i for i in ids if intact_bonds(i) >= min_bonds]


def pieces(ids: Iterable[int], joined: Iterable[tuple[int, int]]) -> dict[int, int]:
    """Each of ``ids`` mapped to one disc of its piece: the discs that the pairs ``joined`` chain
    together (pairs with a disc not among ``ids`` are ignored)."""
    root = {i: i for i in ids}

    def find(i: int) -> int:
        while root[i] != i:
            root[i] = root[root[i]]
            i = root[i]
        return i

    for i, j in joined:
        if i in root and j in root:
            root[find(i)] = find(j)
    return {i: find(i) for i in root}


def largest_piece(ids: Sequence[int]) -> list[int]:
    """The discs of ``ids`` in the largest piece that intact bonds between them hold together
    (ties: the piece of the smallest id), in the order of ``ids``. The others are loose in it:
    once its bonds across a joint are cut, a disc bonded only across it, or a cluster bonded only
    to itself, rattles between the blocks and wedges them."""
    bonded = ((I.id1, I.id2) for i in ids for I in O.bodies[i].intrs() if is_bond(I.phys))
    piece = pieces(ids, bonded)
    members: dict[int, list[int]] = defaultdict(list)
    for i in ids:
        members[piece[i]].append(i)
    main = max(members, key=lambda r: (len(members[r]), -min(members[r])))
    return members[main]


def _intact_now(body_id: int) -> int:
    """A disc's intact bonds now; a deleted disc has none."""
    return intact_bonds(body_id) if O.bodies[body_id] is not None else 0


def rock_breaks(first: int, count: int) -> list[int]:
    """The indices of the ``count`` recorded breaks from the ``first`` on that cracked the rock:
    both discs still rock (``rock``: held by at least two intact bonds) once the last of them is
    over. The others freed a disc, or left it hanging by one bond: a joint can leave a disc or a
    pair bonded across the pore between joint planes by two bonds or fewer, and when a tilt shakes
    it off both bonds go within a millisecond (the first break, of discs each held by two bonds,
    looks like a crack until the second). That is debris coming off, not a crack in the rock.
    A record that does not name the pairs (JCFpm's) counts every break as a crack."""
    law = break_record()
    pairs = list(zip(law.breakId1, law.breakId2))
    end = first + count
    if not pairs:
        return list(range(first, end))
    later = defaultdict(int)  # bonds each disc lost after the window, intact at its end
    for pair in pairs[end:]:
        for i in pair:
            later[i] += 1
    return [k for k in range(first, end) if min(_intact_now(i) + later[i] for i in pairs[k]) >= 2]
