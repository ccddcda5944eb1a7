"""Restitution of a damped contact: a disc hits a wall with a normal dashpot.

For a linear spring-dashpot with critical damping ratio beta the restitution coefficient
is e = exp(-pi beta / sqrt(1 - beta^2)). No gravity, so that the contact starts and ends at
zero overlap.

    ./yade -x -n examples/verification/restitution.py
"""
import math

from yade import O, utils
from yade.utils import readParamsFromTable
from yade.wrapper import ParallelBondMat

from examples import params
from toppling.build import engines
from toppling.build.discs import disc
from toppling.io import output
from toppling.io.params import check
from toppling.run.steps import run_steps

readParamsFromTable(beta=params.TABLE_5_2_COMMON["normalDamping"], radius=0.01,
                    density=params.TABLE_5_1_COMMON["density"], young=1e8, speed=1.0,
                    out="results/restitution", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

check(table, beta="[0, 1)", radius="(0, inf)", density="(0, inf)", young="(0, inf)", speed="(0, inf)")
THICKNESS = 1.0
mat = ParallelBondMat(young=table.young, density=table.density, thickness=THICKNESS, normalDamping=table.beta)
O.bodies.append(utils.wall(0, axis=1, material=mat))
ball = O.bodies.append(disc((0, table.radius * 1.01), table.radius, mat))
O.bodies[ball].state.vel = (0, -table.speed, 0)
O.engines = engines.engines(gravity=(0, 0, 0), timestepper=False)

# Contact period 2 pi sqrt(m/k); 1000 steps per period.
m = O.bodies[ball].state.mass
k = (2 * THICKNESS * table.young) / 2  # two equal disc springs in series
O.dt = 2 * math.pi * math.sqrt(m / k) / 1000
run_steps(int(4 * 0.01 * table.radius / table.speed / O.dt) + 3000)

measured = O.bodies[ball].state.vel[1] / table.speed
reference = math.exp(-math.pi * table.beta / math.sqrt(1 - table.beta**2))
result = output.comparison(measured, reference, "-")
output.write_summary(table.out, output.table_inputs(table), **result)
print(f"restitution {measured:.5f} (closed form {reference:.5f}, rel. error {result['rel_error']:.2e})")
