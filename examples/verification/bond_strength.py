"""A single parallel bond loaded to failure: pulled, bent, sheared, or sheared under compression.

Disc 1 is fixed; disc 2's motion is imposed (all its DOFs blocked, a constant velocity or
spin), slowly enough that the load grows by 0.05 % of the failure load per step. The peak
bond load is compared with the criteria (Potyondy & Cundall 2004):
    pull:   F = sigma_c A                     (tension)
    bend:   M = sigma_c I / R_bar              (tension)
    shear:  F = (c + sigma tan phi_bar) A      (shear; sigma = 0, or `compression` first)

    ./yade -x -n examples/verification/bond_strength.py     # load=pull; or bend, shear, compression [Pa]
"""
import math

from yade import O
from yade.utils import readParamsFromTable
from yade.wrapper import ParallelBondMat

from toppling.build import bonding, engines
from toppling.build.discs import disc
from toppling.io import output
from toppling.io.params import check
from toppling.run.steps import run_steps

readParamsFromTable(load="pull", compression=0.0, radius=0.01, tensile=1e6, cohesion=1e6, friction_deg=30.0,
                    out="results/bond_strength", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

STEPS_TO_BREAK = 2000
if table.load not in ("pull", "bend", "shear"):
    raise ValueError(f"load = {table.load!r} is invalid: it must be one of pull, bend, shear")
check(table, compression="[0, inf)", radius="(0, inf)", tensile="(0, inf)", cohesion="(0, inf)", friction_deg="[0, 90)")
weak_shear = table.load == "shear"  # make the other mode unreachable
mat = ParallelBondMat(young=1e9, density=2700.0, bondYoung=1e9, bondKnKs=2.0, knKs=2.0,
                      bondTensileStrength=1e12 if weak_shear else table.tensile,
                      bondCohesion=table.cohesion if weak_shear else 1e12,
                      bondFrictionAngle=math.radians(table.friction_deg))
R = table.radius
a = O.bodies.append(disc((0, 0), R, mat, fixed=True))
b = O.bodies.append(disc((2 * R, 0), R, mat))
disc = O.bodies[b].state
disc.blockedDOFs = "xyzXYZ"
O.engines = engines.engines(gravity=(0, 0, 0), timestepper=False)
O.dt = 1e-6
bonding.bond_within_gap(1e-9 * R)
phys, law = O.interactions[a, b].phys, engines.bond_law()
A, I, Rb = phys.bondArea, phys.bondInertia, phys.bondRadius

if table.load == "pull":
    reference, unit = table.tensile * A, "N"
    disc.vel = (table.tensile / phys.bondKn / (STEPS_TO_BREAK * O.dt), 0, 0)
elif table.load == "bend":
    reference, unit = table.tensile * I / Rb, "N m"
    disc.angVel = (0, 0, reference / (phys.bondKn * I) / (STEPS_TO_BREAK * O.dt))
else:
    if table.compression:  # squeeze the bond to the normal stress `compression` first
        disc.vel = (-table.compression / phys.bondKn / (200 * O.dt), 0, 0)
        run_steps(200)
    strength = table.cohesion + table.compression * math.tan(mat.bondFrictionAngle)
    disc.vel = (0, strength / phys.bondKs / (STEPS_TO_BREAK * O.dt), 0)

history = []  # (Fn, |Fs|, M) of the intact bond, step by step
while not law.breakMode and O.iter < 20 * STEPS_TO_BREAK:
    O.step()
    if not law.breakMode:
        history.append((phys.bondNormalForce, phys.bondShearForce.norm(), phys.bondMoment))
if not law.breakMode:
    raise RuntimeError("the bond did not break")

sigma_at_break = history[-1][0] / A
column = {"pull": 0, "shear": 1, "bend": 2}[table.load]  # tension, shear force, moment
measured = max(abs(h[column]) for h in history)
if table.load == "shear":
    reference, unit = (table.cohesion + sigma_at_break * math.tan(mat.bondFrictionAngle)) * A, "N"

result, mode = output.comparison(measured, reference, unit), engines.BREAK_MODES[law.breakMode[0]]
output.write_summary(table.out, output.table_inputs(table), **result, mode=mode,
                     sigma_at_break=sigma_at_break, released_energy=law.breakEnergy[0])
fig, ax = output.figure("step", "bond load / predicted strength", f"Bond strength: {table.load}")
ax.plot([abs(h[column]) / reference for h in history])
output.save_figure(fig, table.out, "load")
print(f"{table.load}: peak {measured:.6g} {unit} (criterion {reference:.6g}, rel. error {result['rel_error']:.2e}), "
      f"broke in {mode}")
