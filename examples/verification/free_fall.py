"""Free fall of a disc onto a boundary, thesis §4.1 / Table 4-1.

A disc (R = 50 m, rho = 1000 kg/m3, kn = 1.35e9 N/m; boundary kn = 1.35e11 N/m, no damping,
dt = 3e-4 s) falls 1 m onto a wall. Checks the impact velocity against sqrt(2 g h) = 4.4294
m/s and that, undamped, every bounce returns to the drop height.

Stiffness: a disc spring is k = 2 t Ec (ParallelBondMat), so Ec = kn / (2 t) reproduces the
table's kn for each body; the contact stiffness is the two in series.
The disc starts with the leapfrog half-step velocity -g dt/2 (YADE stores velocities at
mid-step), so that its velocity at time t is -g t exactly.

    ./yade -x -n examples/verification/free_fall.py
"""
import math

from yade import O, utils
from yade.utils import readParamsFromTable
from yade.wrapper import ParallelBondMat, PyRunner

from examples import params
from toppling.build import engines
from toppling.build.discs import disc
from toppling.io import output
from toppling.io.params import check
from toppling.run.steps import run_steps

readParamsFromTable(**params.TABLE_4_1, steps=40000, out="results/free_fall", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

check(table, radius="(0, inf)", density="(0, inf)", kn="(0, inf)", kn_boundary="(0, inf)", drop="(0, inf)",
      g="(0, inf)", dt="(0, inf)", steps="whole [1, inf)")
THICKNESS = 1.0
disc_mat = ParallelBondMat(young=table.kn / (2 * THICKNESS), density=table.density, thickness=THICKNESS)
wall_mat = ParallelBondMat(young=table.kn_boundary / (2 * THICKNESS), density=table.density, thickness=THICKNESS)
O.bodies.append(utils.wall(0, axis=1, material=wall_mat))
ball = O.bodies.append(disc((table.radius + 1.0, table.radius + table.drop), table.radius, disc_mat))
O.bodies[ball].state.vel = (0, -table.g * table.dt / 2, 0)

O.engines = engines.engines(gravity=(0, -table.g, 0), timestepper=False) + [
    PyRunner(iterPeriod=1, command="record()")]
O.dt = table.dt
time, height, velocity = [], [], []


def record():
    """Position at the end of this step, velocity at its middle."""
    s = O.bodies[ball].state
    time.append((O.iter + 1) * O.dt)
    height.append(s.pos[1] - table.radius)  # gap between disc and boundary
    velocity.append(s.vel[1])


run_steps(table.steps)

# Impact: the first step whose end finds the disc touching; interpolate to zero gap.
k = next(i for i, h in enumerate(height) if h <= 0)
t_hit = time[k - 1] + (time[k] - time[k - 1]) * height[k - 1] / (height[k - 1] - height[k])
v_mid_times = [t - O.dt / 2 for t in time]
w = (t_hit - v_mid_times[k]) / O.dt
v_hit = -(velocity[k] + w * (velocity[k + 1] - velocity[k]))
v_ref = math.sqrt(2 * table.g * table.drop)

# Bounce heights: apexes of the gap after each contact.
apexes = [height[i] for i in range(1, len(height) - 1)
          if height[i] > 0 and height[i - 1] < height[i] >= height[i + 1] and i > k]
bounce_error = max(abs(h - table.drop) / table.drop for h in apexes) if apexes else math.inf

result = output.comparison(v_hit, v_ref, "m/s")
output.write_summary(table.out, output.table_inputs(table), **result,
                     bounce_heights=apexes, bounces=len(apexes), bounce_height_max_rel_error=bounce_error,
                     thesis_hdpac={"impact_velocity": params.TABLE_4_1_IMPACT_VELOCITY})
fig, ax = output.figure("time (s)", "gap to boundary (m)", "Free fall, Table 4-1")
ax.plot(time, height)
output.save_figure(fig, table.out, "height")
print(f"impact velocity {v_hit:.5f} m/s (closed form {v_ref:.5f}, rel. error {result['rel_error']:.2e}); "
      f"{len(apexes)} bounces, max height error {bounce_error:.2e}")
