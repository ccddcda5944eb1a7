"""The mechanical energy of a scene, as the leapfrog integrator conserves it."""
from __future__ import annotations

from yade import O
from yade.wrapper import SmoothJointPhys

from toppling.build import engines


def elastic() -> float:
    """Energy in the springs [J]: bonds and rock contacts (the parallel-bond law's) and joints."""
    joints = sum(i.phys.elasticEnergy() for i in O.interactions if isinstance(i.phys, SmoothJointPhys))
    return engines.bond_law().elasticEnergy() + joints


def mechanical() -> float:
    """Kinetic + elastic + gravity's potential energy [J], measured over one step, which it runs.

    YADE integrates with leapfrog: velocities live at half steps, and what leapfrog conserves
    for linear springs pairs the kinetic energy of the velocities before and after the positions,
    sum(m v(t - dt/2) . v(t + dt/2)) / 2, with the energy stored at those positions: the springs'
    from the forces the step computed there, gravity's from the positions before the step moved
    them. Without damping, friction or breaks it stays constant to the integrator's accuracy;
    they only lower it: a rise is the integration's error.
    """
    dynamic = [b for b in O.bodies if b is not None and b.dynamic]
    g = engines.newton().gravity
    before = [(tuple(b.state.vel), b.state.angVel[2], b.state.pos.dot(g)) for b in dynamic]  # copies: live views
    O.step()
    kinetic, potential = 0.0, 0.0
    for b, (v, w, height) in zip(dynamic, before):
        kinetic += 0.5 * b.state.mass * sum(x * y for x, y in zip(v, b.state.vel)) \
            + 0.5 * b.state.inertia[2] * w * b.state.angVel[2]
        potential -= b.state.mass * height
    return kinetic + elastic() + potential
