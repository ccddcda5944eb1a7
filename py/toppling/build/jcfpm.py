"""The same scene in YADE's JCFpm (Scholtès & Donzé 2012), as it ships: a scene built with our
laws (discs, parallel bonds, smooth joints) handed over pair by pair, so both models start from
the same packing, the same bonded pairs and the same joint pairs.

JCFpm has one spring per pair and no bond moment; its joints are found from the discs' states
(``JCFpmState.onJoint``, ``jointNormal1..3``), its stiffness and strengths come from the
material through the pair's radii (kn = 2E R1R2/(R1+R2), ks = ν kn, strengths and joint
stiffness per area times πR²min). How ours maps onto it (docs/jcfpm.md):

* the material (``material``) matches ours for a pair of discs of the reference radius R:
  E = t(Ec + λ̄Ēc)/R, ν = ks/kn of that pair, σt and c times 2λ̄t/(πR), joint stiffness
  times 2λ̄t/(πR), friction our contact friction (JCFpm keeps a bond's friction after it breaks);
* with ``exact`` every existing pair is then given ours exactly: kn, ks (contact + bond, what
  our physics reports), a bond's F̄n,max = σ̄c A, F̄s,max = c̄ A and friction tan φ̄ (so that
  its Mohr-Coulomb line is ours; JCFpm keeps it after the bond breaks, where ours has the
  contact's), a joint's stiffness and friction. Pairs made later (discs that meet during the
  run) get the material's values.
"""
from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass
from typing import Optional

from yade import O, utils
from yade.wrapper import (Bo1_Sphere_Aabb, ForceResetter, GlobalStiffnessTimeStepper, Ig2_Sphere_Sphere_ScGeom,
                          InsertionSortCollider, InteractionLoop, Ip2_JCFpmMat_JCFpmMat_JCFpmPhys, JCFpmMat,
                          JCFpmState, Law2_ScGeom_JCFpmPhys_JointedCohesiveFrictionalPM, NewtonIntegrator,
                          ParallelBondMat, ParallelBondPhys, SmoothJointMat, SmoothJointPhys, Sphere)

from toppling.build import engines, joints
from toppling.checks import require

MAX_JOINTS_PER_DISC = 3  # JCFpmState.jointNormal1..3
MODELS = ("ours", "jcfpm")


def check_model(model: str) -> None:
    if model not in MODELS:
        raise ValueError(f"model = {model!r} is invalid: it must be 'ours' or 'jcfpm'")


def use(model: str, cracks: bool = False) -> None:
    """Hand the scene just built to ``model``: 'ours' leaves it, 'jcfpm' converts it (``convert``,
    recording its cracks with ``cracks``)."""
    check_model(model)
    if model == "jcfpm":
        counts = convert(cracks=cracks)
        print("handed to JCFpm: " + ", ".join(f"{n} {kind}" for kind, n in counts.items()), flush=True)


def material(rock: ParallelBondMat, joint: Optional[SmoothJointMat], radius: float) -> JCFpmMat:
    """JCFpm's material giving a pair of discs of ``radius`` [m] our ``rock``'s intact stiffness
    (contact + bond) and bond strengths, and ``joint``'s stiffness and friction across a joint."""
    require("radius", radius, "(0, inf)")
    t, lam = rock.thickness, rock.bondRadiusMultiplier
    kn = t * rock.young + lam * t * rock.bondYoung  # our pair of equal discs: tEc in series, Ēc/(2R) 2λ̄Rt
    ks = t * rock.young / rock.knKs + lam * t * rock.bondYoung / rock.bondKnKs
    per_area = 2 * lam * t / (math.pi * radius)  # our bond area 2λ̄Rt over JCFpm's πR²
    mat = JCFpmMat(young=kn / radius, poisson=ks / kn, density=rock.density, frictionAngle=rock.frictionAngle,
                   tensileStrength=rock.bondTensileStrength * per_area, cohesion=rock.bondCohesion * per_area)
    if joint is not None:
        joint_area = 2 * joint.radiusMultiplier * joint.thickness / (math.pi * radius)
        mat.jointNormalStiffness = joint.normalStiffness * joint_area
        mat.jointShearStiffness = joint.shearStiffness * joint_area
        mat.jointFrictionAngle = joint.frictionAngle
    return mat


@dataclass(frozen=True)
class Pair:
    """An interaction of ours as JCFpm gets it: ``kind`` 'bond', 'joint' or 'contact', the
    stiffnesses [N/m], strengths [N], friction, and a joint's normal from id1's side to id2's."""
    id1: int
    id2: int
    kind: str
    kn: float
    ks: float
    fn_max: float = 0.0
    fs_max: float = 0.0
    tan_friction: float = 0.0
    normal: Optional[tuple[float, float, float]] = None


def pair_of(interaction) -> Pair:
    phys, ids = interaction.phys, (interaction.id1, interaction.id2)
    if isinstance(phys, SmoothJointPhys):
        if phys.bondState == 1:
            raise ValueError(f"pair {ids}: a bonded smooth joint has no JCFpm counterpart here; install the joints unbonded")
        return Pair(*ids, "joint", phys.kn, phys.ks, tan_friction=phys.tangensOfFrictionAngle,
                    normal=tuple(phys.jointNormal))
    if isinstance(phys, ParallelBondPhys) and phys.bondState == 1:
        return Pair(*ids, "bond", phys.kn, phys.ks, phys.bondTensileStrength * phys.bondArea,
                    phys.bondCohesion * phys.bondArea, phys.bondTanFriction)
    return Pair(*ids, "contact", phys.contactKn if isinstance(phys, ParallelBondPhys) else phys.kn, phys.ks,
                tan_friction=phys.tangensOfFrictionAngle)


def joint_states(pairs: list[Pair]) -> dict[int, list[tuple[float, float, float]]]:
    """Each jointed disc's joint normals, pointing from the joint to the disc (JCFpm's sense)."""
    normals: dict[int, list] = {}
    for p in pairs:
        if p.kind != "joint":
            continue
        for body, sense in ((p.id1, -1.0), (p.id2, 1.0)):
            n = tuple(sense * c for c in p.normal)
            known = normals.setdefault(body, [])
            if all(sum(a * b for a, b in zip(n, m)) < 0.99 for m in known):
                known.append(n)
    crowded = [b for b, ns in normals.items() if len(ns) > MAX_JOINTS_PER_DISC]
    if crowded:
        raise ValueError(f"discs {crowded[:5]} lie on more than {MAX_JOINTS_PER_DISC} joints: JCFpm cannot hold them")
    return normals


def jcfpm_state(state, normals: list) -> JCFpmState:
    new = JCFpmState(se3=state.se3, vel=state.vel, angVel=state.angVel, mass=state.mass, inertia=state.inertia,
                     refPos=state.refPos, refOri=state.refOri)
    new.blockedDOFs = state.blockedDOFs  # a string only the property takes
    new.onJoint, new.joint = bool(normals), len(normals)
    for k, n in enumerate(normals, start=1):
        setattr(new, f"jointNormal{k}", n)
    return new


def jcfpm_engines(gravity, damping: float, safety: float, cracks: bool, ours) -> list:
    """JCFpm's engines; ``ours`` (our Ip2, or None) stays in the dispatcher, idle once no disc is of
    our material, holding the joints' geometry and blocks for the pictures."""
    law = Law2_ScGeom_JCFpmPhys_JointedCohesiveFrictionalPM(smoothJoint=True, recordCracks=cracks,
                                                             Key=f"toppling-{os.getpid()}-{time.time_ns()}")
    ip2 = [Ip2_JCFpmMat_JCFpmMat_JCFpmPhys(cohesiveTresholdIteration=0)] + ([ours] if ours is not None else [])
    return [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
            InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], ip2, [law]),
            GlobalStiffnessTimeStepper(timestepSafetyCoefficient=safety, timeStepUpdateInterval=100),
            NewtonIntegrator(gravity=gravity, damping=damping)]


def mean_radius() -> float:
    radii = [b.shape.radius for b in O.bodies if b is not None and isinstance(b.shape, Sphere)]
    return sum(radii) / len(radii)


def convert(exact: bool = True, safety: float = 0.5, cracks: bool = False) -> dict[str, int]:
    """Turn the current scene (our discs, bonds and smooth joints) into JCFpm's: every disc of
    ParallelBondMat gets ``material`` at the discs' mean radius (the first joint set's values for
    joints) and a JCFpmState, the engines become JCFpm's (gravity and local damping kept, time
    step by GlobalStiffnessTimeStepper with ``safety``), and every bond, joint and contact pair
    is made again, bonds cohesive; with ``exact`` each gets ours (module docstring). Returns how
    many pairs of each kind, and ``misread``: pairs JCFpm took for another kind than ours.
    With ``cracks`` JCFpm records its cracks (``CrackRecord``; a file in the working directory)."""
    engines.check_safety(safety)
    pairs = [pair_of(i) for i in O.interactions if i.isReal]
    rocks = {b.material for b in O.bodies if b is not None and isinstance(b.material, ParallelBondMat)}
    if len(rocks) != 1:
        raise ValueError(f"the scene has {len(rocks)} rock materials: the conversion needs exactly one ParallelBondMat")
    joint_sets = [m for m in O.materials if isinstance(m, SmoothJointMat)]
    mat = material(rocks.pop(), joint_sets[0] if joint_sets else None, mean_radius())
    newton = engines.newton()
    gravity, damping = newton.gravity, newton.damping
    try:
        ours = joints.rock_functor()
    except LookupError:
        ours = None
    normals = joint_states(pairs)
    O.materials.append(mat)
    O.interactions.clear()
    for b in O.bodies:
        if b is not None and isinstance(b.material, ParallelBondMat):
            b.material, b.state = mat, jcfpm_state(b.state, normals.get(b.id, []))
    O.engines = jcfpm_engines(gravity, damping, safety, cracks, ours)
    ip2 = engines.functor(Ip2_JCFpmMat_JCFpmMat_JCFpmPhys, "physDispatcher")
    counts = {"bond": 0, "joint": 0, "contact": 0, "misread": 0}
    for p in pairs:
        ip2.cohesiveTresholdIteration = O.iter + 1 if p.kind == "bond" else 0
        phys = utils.createInteraction(p.id1, p.id2).phys
        counts[p.kind] += 1
        counts["misread"] += (p.kind == "joint") != phys.isOnJoint or (p.kind == "bond") != phys.isCohesive
        if exact:
            phys.kn, phys.ks, phys.tanFrictionAngle = p.kn, p.ks, p.tan_friction
            if phys.isCohesive:
                phys.FnMax, phys.FsMax = p.fn_max, p.fs_max
    ip2.cohesiveTresholdIteration = 0  # contacts made from now on are frictional, as ours
    return counts


class CrackRecord:
    """JCFpm's cracks as our law records its breaks: breakPosition, breakMode (2 tension, 3 shear),
    breakTime, breakNormal, breakSize, breakEnergy, read from the file JCFpm's law writes with
    ``recordCracks`` (``cracks_<Key>.txt`` in the working directory), up to the scene's iteration
    (a run resumed from a checkpoint leaves out the cracks of the run it replaces; it must be
    resumed from the same directory). JCFpm does not say which pair broke: breakId1 and breakId2
    are empty."""
    breakId1 = breakId2 = ()

    def __init__(self, path: str):
        self.path = path
        rows = []
        if os.path.exists(path):
            with open(path) as f:
                next(f, None)  # the header
                rows = [[float(v) for v in line.split()] for line in f if line.strip()]
        rows = [r for r in rows if r[0] <= O.iter]
        self.breakTime = [r[1] for r in rows]
        self.breakPosition = [tuple(r[2:5]) for r in rows]
        self.breakMode = [2 if r[5] == 1 else 3 for r in rows]
        self.breakSize = [r[6] for r in rows]
        self.breakNormal = [tuple(r[7:10]) for r in rows]
        self.breakEnergy = [r[10] for r in rows]

    @classmethod
    def of_scene(cls) -> "CrackRecord":
        """The record of the scene's JCFpm law (LookupError if it has none or it records no cracks)."""
        law = engines.functor(Law2_ScGeom_JCFpmPhys_JointedCohesiveFrictionalPM)
        if not law.recordCracks:
            raise LookupError("the scene's JCFpm law records no cracks: convert(cracks=True)")
        return cls(f"cracks_{law.Key}.txt")


def keep_cracks(out: str) -> None:
    """Move the scene's JCFpm cracks' file (if it records any) from the working directory into
    ``out`` (as jcfpm_cracks.txt): the run is over."""
    try:
        path = CrackRecord.of_scene().path
    except LookupError:  # not a JCFpm scene, or one that records no cracks
        return
    if os.path.exists(path):
        os.replace(path, os.path.join(out, "jcfpm_cracks.txt"))
