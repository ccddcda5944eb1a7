"""Small bonded scenes shared by the physics tests."""
import math

from yade import O
from yade.wrapper import ParallelBondMat

from toppling import bonding, scene

R = 0.01  # disc radius of the test scenes [m]


def material(**overrides) -> ParallelBondMat:
    """Rock-like discs with stiff, strong bonds unless overridden."""
    params = dict(young=1e9, density=2700.0, thickness=1.0, knKs=2.0, frictionAngle=math.atan(0.5),
                  bondYoung=1e9, bondKnKs=2.0, bondRadiusMultiplier=1.0)
    params.update(overrides)
    return ParallelBondMat(**params)


def hex_lattice(rows: int, cols: int, mat, fixed_bottom: bool = False) -> list[int]:
    """Touching discs of radius R on a triangular lattice, all bonded."""
    ids = []
    for j in range(rows):
        for i in range(cols):
            x = 2 * R * i + (R if j % 2 else 0)
            y = math.sqrt(3) * R * j
            ids.append(O.bodies.append(scene.disc((x, y), R, mat, fixed=fixed_bottom and j == 0)))
    return ids


def bonded_lattice(rows, cols, mat, gravity=(0, 0, 0), fixed_bottom=False, **engine_kw) -> list[int]:
    """A hex lattice with engines and every touching pair bonded."""
    ids = hex_lattice(rows, cols, mat, fixed_bottom)
    O.engines = scene.engines(gravity=gravity, **engine_kw)
    bonding.bond_within_gap(gap=1e-6 * R)
    return ids


def kinetic_energy() -> float:
    """Translational + rotational kinetic energy of the discs (disc mass and inertia)."""
    return sum(0.5 * b.state.mass * b.state.vel.squaredNorm() + 0.5 * b.state.inertia[2] * b.state.angVel[2] ** 2
               for b in O.bodies if b.isDynamic)
