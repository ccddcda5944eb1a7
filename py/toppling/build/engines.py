"""The engine list of a bonded-disc scene and access to its parts (laws, damping, time step)."""
from __future__ import annotations

import math
from typing import Sequence

from yade import O
from yade.wrapper import (Bo1_Box_Aabb, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, DiscInteractionLoop, DiscNewtonIntegrator,
                          ForceResetter,
                          GlobalStiffnessTimeStepper, Ig2_Box_Sphere_ScGeom,
                          Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom,
                          InsertionSortCollider, InteractionLoop,
                          Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys,
                          Law2_ScGeom_ParallelBondPhys_ParallelBond,
                          Law2_ScGeom_SmoothJointPhys_SmoothJoint, NewtonIntegrator)

from toppling.checks import require


G = 9.81  # [m/s2]


def engines(gravity=(0.0, -G, 0.0), local_damping: float = 0.0,
            timestepper: bool = True, safety: float = 0.5, extra: Sequence = (), fast: bool = True) -> list:
    """The engine list of a bonded-disc scene: collider, parallel-bond and smooth-joint laws, Newton.

    ``local_damping`` is NewtonIntegrator's non-viscous damping (PFC's local damping);
    ``timestepper`` adds GlobalStiffnessTimeStepper, which sees bond stiffness. ``fast``: the
    disc path (DiscInteractionLoop, DiscNewtonIntegrator), else YADE's generic InteractionLoop and
    NewtonIntegrator (the same results).
    """
    check_damping(local_damping)
    check_safety(safety)
    loop_class = DiscInteractionLoop if fast else InteractionLoop
    loop = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb(), Bo1_Box_Aabb()]),
        loop_class(
            [Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()],
            [Ip2_ParallelBondMat_ParallelBondMat_ParallelBondPhys()],
            [Law2_ScGeom_ParallelBondPhys_ParallelBond(), Law2_ScGeom_SmoothJointPhys_SmoothJoint()]),
    ]
    if timestepper:
        loop.append(GlobalStiffnessTimeStepper(timestepSafetyCoefficient=safety,
                                               timeStepUpdateInterval=100))
    loop.append((DiscNewtonIntegrator if fast else NewtonIntegrator)(gravity=gravity, damping=local_damping))
    return loop + list(extra)


def check_damping(damping: float, name: str = "local_damping") -> None:
    """Raise ValueError unless ``damping`` (NewtonIntegrator's local damping, called ``name``
    where the user set it) is in [0, 1)."""
    require(name, damping, "[0, 1)")


def newton() -> NewtonIntegrator:
    """The scene's NewtonIntegrator (it holds gravity and the local damping)."""
    for engine in O.engines:
        if isinstance(engine, NewtonIntegrator):
            return engine
    raise LookupError("no NewtonIntegrator in O.engines; build them with toppling.build.engines.engines()")


def set_local_damping(damping: float) -> None:
    """Set the scene's NewtonIntegrator local damping (e.g. one value to settle, another to load)."""
    check_damping(damping)
    newton().damping = damping


def check_safety(safety: float, name: str = "safety") -> None:
    """Raise ValueError unless ``safety`` (GlobalStiffnessTimeStepper's coefficient of
    sqrt(2 m/K), called ``name`` where the user set it) is in (0, 1]."""
    require(name, safety, "(0, 1]")


def limit_timestep() -> None:
    """Make GlobalStiffnessTimeStepper's time step account for stress-free bonds.

    It skips interactions that carry no force, so right after bonding it would ignore the new
    bonds; the law's criticalTimeStep() counts them. Called by toppling.bonding.
    """
    steppers = [e for e in O.engines if isinstance(e, GlobalStiffnessTimeStepper)]
    if not steppers:
        return
    stepper = steppers[0]
    dt = stepper.timestepSafetyCoefficient * bond_law().criticalTimeStep()
    if math.isinf(dt):
        return
    stepper.defaultDt = dt  # used while nothing carries force (e.g. the first step)
    stepper.previousDt = min(stepper.previousDt, dt)
    O.dt = min(O.dt, dt) if O.iter > 0 else dt


def set_fast(fast: bool) -> None:
    """Run the scene on the disc path (DiscInteractionLoop, DiscNewtonIntegrator) or on YADE's generic
    InteractionLoop and NewtonIntegrator, with the same functors and settings."""
    engines = list(O.engines)
    loops = [k for k, e in enumerate(engines) if isinstance(e, InteractionLoop)]
    if not loops:
        raise LookupError("no InteractionLoop in O.engines; build them with toppling.build.engines.engines()")
    functors = [getattr(engines[loops[0]], d).functors for d in ("geomDispatcher", "physDispatcher", "lawDispatcher")]
    engines[loops[0]] = (DiscInteractionLoop if fast else InteractionLoop)(*functors)
    for k, e in enumerate(engines):
        if isinstance(e, NewtonIntegrator):
            engines[k] = newton = (DiscNewtonIntegrator if fast else NewtonIntegrator)(**e.dict())
            for collider in engines:  # it keeps the integrator it asks for the bodies' largest displacement
                if isinstance(collider, InsertionSortCollider):
                    collider.newton = newton
    O.engines = engines


def functor(cls, dispatcher: str = "lawDispatcher"):
    """The scene's InteractionLoop functor of class ``cls`` (from its ``dispatcher``)."""
    for engine in O.engines:
        if isinstance(engine, InteractionLoop):
            for f in getattr(engine, dispatcher).functors:
                if isinstance(f, cls):
                    return f
    raise LookupError(f"no {cls.__name__} in O.engines; build them with toppling.build.engines.engines()")


BREAK_MODES = {2: "tension", 3: "shear"}  # the bond law's breakMode codes


def bond_law() -> Law2_ScGeom_ParallelBondPhys_ParallelBond:
    """The scene's parallel-bond Law2 functor (holds the break records)."""
    return functor(Law2_ScGeom_ParallelBondPhys_ParallelBond)


def break_record():
    """The scene's record of broken bonds: our parallel-bond law, or in a scene handed to JCFpm
    its cracks read as our law keeps them (``toppling.build.jcfpm.CrackRecord``): breakPosition,
    breakMode (BREAK_MODES), breakTime, breakId1 and breakId2."""
    try:
        return bond_law()
    except LookupError:
        from toppling.build import jcfpm  # it builds on this module
        return jcfpm.CrackRecord.of_scene()


def broken_bonds() -> int:
    """How many bonds have broken so far (in either mode)."""
    return len(break_record().breakMode)
