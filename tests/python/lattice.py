"""Small bonded scenes shared by the physics tests."""
import math

from yade import O
from yade.wrapper import ParallelBondMat

from toppling.build import bonding, boundary, engines
from toppling.build.discs import disc

R = 0.01  # disc radius of the test scenes [m]


def material(**overrides) -> ParallelBondMat:
    """Rock-like discs with stiff, strong bonds unless overridden."""
    params = dict(young=1e9, density=2700.0, thickness=1.0, knKs=2.0, frictionAngle=math.atan(0.5),
                  bondYoung=1e9, bondKnKs=2.0, bondRadiusMultiplier=1.0)
    params.update(overrides)
    return ParallelBondMat(**params)


def hex_lattice(rows: int, cols: int, mat, fixed_bottom: bool = False, gap: float = 0.0) -> list[int]:
    """Discs of radius R on a triangular lattice, ``gap`` apart (touching by default)."""
    ids = []
    pitch = 2 * R + gap
    for j in range(rows):
        for i in range(cols):
            x = pitch * i + (pitch / 2 if j % 2 else 0)
            y = math.sqrt(3) / 2 * pitch * j
            ids.append(O.bodies.append(disc((x, y), R, mat, fixed=fixed_bottom and j == 0)))
    return ids


def bonded_lattice(rows, cols, mat, gravity=(0, 0, 0), fixed_bottom=False, gap=0.0, **engine_kw) -> list[int]:
    """A hex lattice with engines and every neighbour pair bonded."""
    ids = hex_lattice(rows, cols, mat, fixed_bottom, gap)
    O.engines = engines.engines(gravity=gravity, **engine_kw)
    bonding.bond_within_gap(gap=gap + 1e-6 * R)
    return ids


def pull_until_broken(body_id: int) -> float:
    """Pull disc ``body_id`` off along +y until a bond breaks; the time of the step that broke it."""
    boundary.move([body_id], (0, 0.01))
    while not engines.bond_law().breakMode:
        when = O.time
        O.step()
    return when
