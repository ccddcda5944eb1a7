"""Cantilever of 11 bonded discs under tip force and moment, thesis §4.2 / Tables 4-2, 4-3.

Beam: L = 200 in, section 2R = 16 in x t = 1 in, E = 68.95 GPa (2024-T3 aluminium, G = 26
GPa), tip F = 4.448 kN and M = 11.30 kN m, root fixed. Closed form (Euler-Bernoulli):
    delta = F L^3 / (3 E I) + M L^2 / (2 E I) = 34.7 mm  (thesis HDPAC: 34.715 mm).

Discretisation (PFC's "equivalent elastic cylinders"): 11 touching discs of radius
L/20 = 10 in, so centres are L/10 apart and the bond length R1 + R2 equals the segment
length; bond radius multiplier 0.8 gives a bond section 2 R_bar = 16 in, whose
I = 2/3 R_bar^3 t equals t h^3 / 12 of the beam. Bond modulus E, bond kn/ks = E/G so the
bonds' shear stiffness is G A / L. Discrete-beam error (midpoint rule over 10 segments):
-0.25 % on the force term, plus +0.2 % shear deflection.

    ./yade -x -n examples/verification/cantilever.py
"""

from yade import O
from yade.utils import readParamsFromTable
from yade.wrapper import ParallelBondMat

from examples import params
from toppling.build import bonding, engines
from toppling.build.discs import disc
from toppling.io import output
from toppling.io.params import check
from toppling.run.steps import run_steps

BEAM, LOAD = params.TABLE_4_2, params.TABLE_4_3
readParamsFromTable(force=LOAD["force"], moment=LOAD["moment"], young=BEAM["young"], shear_modulus=BEAM["shear_modulus"],
                    discs=11, out="results/cantilever", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

check(table, force="(-inf, inf)", moment="(-inf, inf)", young="(0, inf)", shear_modulus="(0, inf)",
      discs="whole [2, inf)")
L, T, H = BEAM["length"], BEAM["thickness"], BEAM["depth"]
R = L / (2 * (table.discs - 1))
mat = ParallelBondMat(young=table.young, density=BEAM["density"], thickness=T, bondYoung=table.young,
                      bondRadiusMultiplier=(H / 2) / R, bondKnKs=table.young / table.shear_modulus,
                      frictionAngle=0.0)
ids = [O.bodies.append(disc((2 * R * i, 0), R, mat, fixed=(i == 0))) for i in range(table.discs)]
tip = ids[-1]
O.engines = engines.engines(gravity=(0, 0, 0), local_damping=0.7)
bonds = bonding.bond_within_gap(gap=1e-9 * R)

O.forces.setPermF(tip, (0, table.force, 0))
O.forces.setPermT(tip, (0, 0, table.moment))
deflection = []
while True:  # run until the tip stops moving (relative change < 1e-7 over 2000 steps)
    run_steps(2000)
    deflection.append(O.bodies[tip].state.displ()[1])
    if len(deflection) > 2 and abs(deflection[-1] - deflection[-2]) < 1e-7 * abs(deflection[-1]):
        break
    if len(deflection) > 500:
        raise RuntimeError("cantilever did not reach equilibrium in 1e6 steps")

I = T * H**3 / 12
reference = table.force * L**3 / (3 * table.young * I) + table.moment * L**2 / (2 * table.young * I)
result = output.comparison(deflection[-1] * 1e3, reference * 1e3, "mm")
output.write_summary(table.out, output.table_inputs(table), **result, bonds=bonds, steps=O.iter,
                     thesis_hdpac_mm=LOAD["hdpac_tip_mm"])
fig, ax = output.figure("x (m)", "deflection (mm)", "Cantilever, Tables 4-2/4-3")
xs = [O.bodies[i].state.pos[0] for i in ids]
ax.plot(xs, [O.bodies[i].state.displ()[1] * 1e3 for i in ids], "o-", label="bonded discs")
ax.plot(xs, [(table.force * x**2 * (3 * L - x) / 6 + table.moment * x**2 / 2) / (table.young * I) * 1e3 for x in xs],
        "k--", label="beam theory")
ax.legend()
output.save_figure(fig, table.out, "deflection")
print(f"tip deflection {result['measured']:.3f} mm (closed form {result['reference']:.3f} mm, rel. error {result['rel_error']:.2e})")
