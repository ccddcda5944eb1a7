"""A block of bonded discs on a fixed base across one horizontal joint, on a tilting table.

The scene of the block-on-incline and tilt tests (thesis §4.4): base and block are packed as
one polygon and cut by the joint at y = 0 (thesis Fig 3-4), so the interface is as rough as
the packing; tilt with ``toppling.load.tilting.set_tilt`` (gravity rotated, thesis Fig 5-7).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Optional

from yade import O
from yade.wrapper import JointSetGeometry, ParallelBondMat, SmoothJointMat

from toppling.build import bonding, engines, geometry, joints, packing
from toppling.build.discs import disc
from toppling.run.steps import check_stable, run_steps, steps_in


@dataclass
class BlockOnBase:
    block: list          # ids of the block's discs
    base: list           # ids of the fixed base's discs
    toe: int             # the block's disc nearest its downhill base corner
    b: float
    h: float


BOND_GAP = 0.05  # x Rmin


def build(b: float, h: float, rmin: float, rmax: float, rock: dict, joint_friction_deg: float,
          smooth: bool = True, porosity: float = 0.2, seed: int = 1, joint_stiffness_scale: float = 1.0,
          bond_gap: float = BOND_GAP, face_closure: bool = False) -> BlockOnBase:
    """Pack, bond (unbreakable bonds) and joint a b x h block on a base; gravity vertical.

    ``rock``: ParallelBondMat parameters. Discs within ``bond_gap`` x Rmin are bonded, and those
    pairs across the joint become its contacts. The joint has the bonds' stiffness per area (times
    ``joint_stiffness_scale``) and friction ``joint_friction_deg``; ``smooth=False`` only cuts the
    bonds across it (plain disc contacts with that friction). ``face_closure``: see
    ``joints.install_joints``. The block is its largest bonded
    piece: discs the joint leaves loose in it (bonded only across the joint, or only to each
    other) are deleted, as floaters are.
    """
    width, thickness, x0 = 2 * b + 2 * h, 10 * rmax, 0.5 * b  # room downhill (+x) to slide or topple
    section = [(0, -thickness), (width, -thickness), (width, 0), (x0 + b, 0), (x0 + b, h), (x0, h), (x0, 0), (0, 0)]
    discs = packing.pack_polygon(geometry.region(section), rmin, rmax, porosity, seed=seed).discs
    mat = ParallelBondMat(frictionAngle=math.radians(joint_friction_deg), bondTensileStrength=1e12,
                          bondCohesion=1e12, **rock)
    base = [O.bodies.append(disc((x, y), r, mat, fixed=True)) for x, y, r in discs if y < 0]
    block = [O.bodies.append(disc((x, y), r, mat)) for x, y, r in discs if y >= 0]
    O.engines = engines.engines(gravity=(0, -engines.G, 0), local_damping=0.0)
    floaters = set(bonding.remove_floaters(bond_gap * rmin, ids=block))
    block = [i for i in block if i not in floaters]
    if not block:
        raise ValueError(f"rmax = {rmax:g} is too large for a {b:g} x {h:g} m block: no disc of it is bonded to "
                         "another (it must be small enough for the block to be a piece of bonded discs)")
    bonding.bond_within_gap(bond_gap * rmin)  # also which pairs across the joint get a joint contact
    interface, box = JointSetGeometry(origin=(0, 0), dip=0), ((-1, -1), (width + 1, h + 1))
    if smooth:
        stiffness = joint_stiffness_scale * mat.bondYoung / (2 * rmin)
        mechanics = SmoothJointMat(normalStiffness=stiffness, shearStiffness=stiffness / mat.bondKnKs,
                                   frictionAngle=math.radians(joint_friction_deg))
        joints.install_joints([(interface, mechanics)], *box, face_closure=face_closure)
    else:
        joints.cut_bonds(interface, *box)
    held = bonding.largest_piece(block)  # the block is one rigid piece; what the joint set loose goes
    for i in set(block) - set(held):
        O.bodies.erase(i)
    block = held
    toe = min(block, key=lambda i: (O.bodies[i].state.pos - (x0 + b, 0, 0)).norm())
    return BlockOnBase(block, base, toe, b, h)


def settle(seconds: float, damping: float = 0.5) -> None:
    """Run ``seconds`` with NewtonIntegrator's local damping, then switch it off again."""
    engines.set_local_damping(damping)
    run_steps(steps_in(seconds))
    engines.set_local_damping(0.0)


def toe_translation(scene_: BlockOnBase, x_start: float) -> float:
    """Displacement of the block's toe along the incline [m]."""
    return O.bodies[scene_.toe].state.pos[0] - x_start


def mean_spin_deg(ids) -> float:
    """Mean rotation of the discs about z [deg]."""
    total = 0.0
    for i in ids:
        axis, angle = O.bodies[i].state.ori.toAxisAngle()
        total += angle * axis[2]
    return math.degrees(total / len(ids))


def mode(translation: float, rotation_deg: float, b: float) -> str:
    """How a block b wide moved: slide if its toe went further than b/10 along the incline,
    topple if it turned more than 5°, both, or stable."""
    slides, topples = translation > 0.1 * b, abs(rotation_deg) > 5.0
    return "slide+topple" if slides and topples else "slide" if slides else "topple" if topples else "stable"


def run_to_mode(setup: BlockOnBase, duration: float, every: int = 200,
                on_chunk: Optional[Callable[[], None]] = None) -> list[tuple[float, float, float]]:
    """Run the tilted block until it has clearly failed (turned more than 30° or its toe moved
    further than b; judged as it starts: once toppled over, its toe skids too) or for
    ``duration`` [s]. Returns (time, toe translation [m], mean rotation [deg]) every ``every``
    steps, after ``on_chunk()`` (e.g. a measurement); stops with check_stable's message if the
    run went unstable."""
    x_start, start, history = O.bodies[setup.toe].state.pos[0], O.time, []
    while O.time - start < duration and not (history and (abs(history[-1][2]) > 30 or history[-1][1] > setup.b)):
        run_steps(every)
        if on_chunk:
            on_chunk()
        history.append((O.time, toe_translation(setup, x_start), mean_spin_deg(setup.block)))
        check_stable()
    return history
