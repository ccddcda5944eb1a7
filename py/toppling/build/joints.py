"""Install pre-existing joints: bonded pairs that straddle a joint become smooth joints."""
from __future__ import annotations

import math
from typing import Sequence

from yade import O, utils
from yade.wrapper import (Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys,
                          JointSetGeometry, JointSystem, SmoothJointMat, SmoothJointPhys)

from toppling.build import bonding
from toppling.build.engines import functor, limit_timestep
from toppling.checks import require


def rock_functor() -> Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys:
    """The Ip2 that decides between rock (parallel bond) and joint (smooth joint)."""
    return functor(Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys, "physDispatcher")


def blocks() -> list[int]:
    """The block of every body (by id; -1: none) as the installed joints make them; [] before any joint."""
    system = rock_functor().joints
    return list(system.blockOfBody) if system is not None else []


def is_persistent(geometry: JointSetGeometry) -> bool:
    """A set whose joints run through the whole section (no rock bridges, not explicit)."""
    return not geometry.segmentStarts and geometry.bridgeLength == 0


def joint_normal(geometry: JointSetGeometry) -> tuple[float, float, float]:
    """Unit normal of a set's joint lines, from its dip (explicit segments: the set's ``dip``)."""
    a = math.radians(geometry.dip)
    return (-math.sin(a), math.cos(a), 0.0)


def check_segments_inside(geometry: JointSetGeometry, lo, hi) -> None:
    """Raise ValueError naming the first explicit joint of ``geometry`` with an end outside the box lo..hi."""
    for k, (a, b) in enumerate(zip(geometry.segmentStarts, geometry.segmentEnds)):
        if not all(lo[d] <= p[d] <= hi[d] for p in (a, b) for d in (0, 1)):
            raise ValueError(f"JointSetGeometry.segmentStarts[{k}], segmentEnds[{k}] = ({a[0]:g}, {a[1]:g}), "
                             f"({b[0]:g}, {b[1]:g}) are invalid: an explicit joint must lie inside the box "
                             f"lo = ({lo[0]:g}, {lo[1]:g}), hi = ({hi[0]:g}, {hi[1]:g}) m")


def install_joints(sets: Sequence[tuple[JointSetGeometry, SmoothJointMat]], lo, hi,
                   pieces: bool = True, face_closure: bool = False) -> JointSystem:
    """Install joint sets (geometry, mechanics) in the current scene, within the box lo..hi.

    Every interaction whose centre-to-centre segment crosses a joint loses its bond and gets
    the smooth joint of that set (thesis §3.2.4), oriented by the geometry's dip. Discs are
    given the block they lie in, so contacts that form later between blocks are smooth joints
    too: with ``pieces`` the piece of rock (``assign_pieces``), else only the band of every
    persistent set, which leaves a block that slides along a joint of explicit segments or
    with rock bridges to make plain, interlocking disc contacts with the rock it slides over.
    With ``face_closure`` a joint contact made later starts with the closure of the two discs'
    faces instead of stress-free (:yref:`JointSystem.faceClosure`). Returns the scene's JointSystem.
    """
    ip2 = rock_functor()
    system = ip2.joints if ip2.joints is not None else JointSystem()
    pairs = []
    for geometry, mechanics in sets:
        check_segments_inside(geometry, lo, hi)
        mechanics.normal = joint_normal(geometry)
        system.jointMaterials = list(system.jointMaterials) + [O.materials.append(mechanics)]
        pairs += system.addCrossingPairs(geometry, len(system.jointMaterials) - 1, lo, hi)
    system.faceClosure = face_closure
    system.assignBlocks([g for g, _ in sets if is_persistent(g)])
    ip2.joints = system
    for i, j in pairs:  # the Ip2 now makes them smooth joints
        O.interactions.erase(i, j)
        utils.createInteraction(i, j)
    if pieces:
        assign_pieces(system)
    limit_timestep()
    return system


def trace(centre, normal, half: float) -> tuple[tuple[float, float], tuple[float, float]]:
    """The ends of a joint's trace through ``centre``: ``half`` along the joint either way (the
    joint runs at right angles to its ``normal``)."""
    along = (-normal[1] * half, normal[0] * half)
    return (centre[0] - along[0], centre[1] - along[1]), (centre[0] + along[0], centre[1] + along[1])


def joint_traces(positions: dict[int, tuple[float, float]]) -> list[tuple[tuple, tuple, int]]:
    """The installed joints as drawn on a picture: per joint pair of the scene's JointSystem, a
    segment of its set's joint line through the pair's midpoint, as wide as the smaller disc,
    with the discs at ``positions`` (id -> (x, y); e.g. as built). ((x0, y0), (x1, y1), set)."""
    system = rock_functor().joints
    if system is None:
        return []
    normals = [tuple(O.materials[m].normal)[:2] for m in system.jointMaterials]
    traces = []
    for i, j, s in zip(system.pairId1, system.pairId2, system.pairSet):
        (xi, yi), (xj, yj) = positions[i][:2], positions[j][:2]
        half = min(O.bodies[i].shape.radius, O.bodies[j].shape.radius)
        traces.append((*trace((0.5 * (xi + xj), 0.5 * (yi + yj)), normals[s], half), s))
    return traces


def assign_pieces(system: JointSystem) -> None:
    """Split the blocks of ``system`` into pieces of rock: discs joined by a chain of intact
    bonds within one block. Joints are what cut bonds, so a piece is bounded by joints. A disc
    without an intact bond in its block is a piece of its own: its new contacts are joints."""
    blocks = list(system.blockOfBody)
    piece = bonding.pieces(range(len(blocks)), ((I.id1, I.id2) for I in O.interactions if I.isReal and
                                                getattr(I.phys, "bondState", 0) == 1 and blocks[I.id1] == blocks[I.id2] >= 0))
    labels: dict[int, int] = {}
    system.blockOfBody = [labels.setdefault(piece[i], len(labels)) if b >= 0 else -1 for i, b in enumerate(blocks)]


def cut_bonds(geometry: JointSetGeometry, lo, hi) -> int:
    """Only unbond the pairs across a joint: they go on as plain frictional disc contacts
    (what smooth joints replace; for comparison). Returns the number of pairs cut."""
    pairs = JointSystem().crossingPairs(geometry, lo, hi)
    for i, j in pairs:
        O.interactions.erase(i, j)  # the collider makes them plain contacts again
    return len(pairs)


def bond_contacts(tensile_strength: float, cohesion: float) -> int:
    """Bond every joint contact that exists now (a cemented joint), keeping the forces it
    carries: installed after the scene has settled, the bonds start from its settled state
    instead of resisting the settling. Returns how many were bonded."""
    require("tensile_strength", tensile_strength, "[0, inf)")
    require("cohesion", cohesion, "[0, inf)")
    count = 0
    for i in O.interactions:
        if isinstance(i.phys, SmoothJointPhys) and i.phys.jointNormalForce >= 0:
            i.phys.tensileStrength, i.phys.cohesion, i.phys.bondState = tensile_strength, cohesion, 1
            count += 1
    return count
