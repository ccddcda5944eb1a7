"""Numerical UCS test of the block material, thesis §5.2.3 / Table 5-1.

A 4.7 x 10 cm specimen of discs (R 1-2.5 mm), bonded, compressed between platens: the discs
within Rmax of the top and bottom edges move towards each other at `velocity` (0.01 m/s in
the thesis). Axial stress = platen force / (width x t); axial strain = platen closure /
height. Reported: Young's modulus (secant between 10 % and 50 % of the peak) and the peak
(UCS), against the laboratory UCS of the blocks, 45-65 kPa, mean 56.7 kPa (Amini et al.
2015, quoted in §5.2.3).

Differences from the thesis, stated: porosity 0.18 instead of 0.12 (0.12 needs locked-in
overlap, see README), bond radius multiplier 1 (not given), bond gap `bond_gap` x Rmin.

    ./yade -x -n examples/validation/ucs.py            # test=1 (Table 5-1 column)
"""
import math

from yade import O
from yade.utils import readParamsFromTable
from yade.wrapper import ParallelBondMat

from toppling import bonding, boundary, geometry, output, packing, scene

readParamsFromTable(test=1, rmin=1e-3, rmax=2.5e-3, porosity=0.18, bond_gap=0.1, relax_steps=500, velocity=0.01, seed=1, out="results/ucs",
                    noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

# Table 5-1, tests 1-3 (Ec, kn/ks, Ebar, kbar n/s, tensile, cohesion, bond friction).
TABLE_5_1 = {
    1: dict(young=12.05e6, knKs=1.3, bondYoung=12e6, bondKnKs=1.8, bondTensileStrength=19.7e3, bondCohesion=25e3,
            bondFrictionAngle=math.radians(10)),
    2: dict(young=7.05e6, knKs=1.8, bondYoung=7.0e6, bondKnKs=1.8, bondTensileStrength=13.5e3, bondCohesion=29e3,
            bondFrictionAngle=math.radians(15)),
    3: dict(young=13.05e6, knKs=1.3, bondYoung=13e6, bondKnKs=1.8, bondTensileStrength=19.7e3, bondCohesion=25e3,
            bondFrictionAngle=math.radians(15)),
}
COMMON = dict(density=2880.0, frictionAngle=math.atan(0.45), bondNormalDamping=0.2, normalDamping=0.13)
LAB_UCS = 56.7e3  # Pa, mean of the laboratory tests
WIDTH, HEIGHT, T = 0.047, 0.10, 1.0

if table.test not in TABLE_5_1:
    raise ValueError(f"test = {table.test} is invalid: it must be 1, 2 or 3 (Table 5-1 columns)")
specimen = geometry.region([(0, 0), (WIDTH, 0), (WIDTH, HEIGHT), (0, HEIGHT)])
discs = packing.pack_polygon(specimen, table.rmin, table.rmax, table.porosity, seed=table.seed).discs
rock = ParallelBondMat(thickness=T, **COMMON, **TABLE_5_1[table.test])
ids = scene.add_discs(discs, rock)
O.engines = scene.engines(gravity=(0, 0, 0), local_damping=0.9)
O.run(table.relax_steps, True)  # free and damped: the packing's overlaps relax, else they break the weak bonds
O.engines[-1].damping = 0.0
bonds = bonding.bond_within_gap(table.bond_gap * table.rmin)
top = boundary.near([((0, HEIGHT), (WIDTH, HEIGHT))], table.rmax)
bottom = boundary.near([((0, 0), (WIDTH, 0))], table.rmax)
boundary.move(top, (0, -table.velocity))
boundary.move(bottom, (0, table.velocity))

law, curve, t0 = scene.bond_law(), [(0.0, 0.0)], O.time
while True:
    O.run(100, True)
    strain = 2 * table.velocity * (O.time - t0) / HEIGHT
    force = sum(O.forces.f(i)[1] for i in top) - sum(O.forces.f(i)[1] for i in bottom)  # the specimen pushes out
    curve.append((strain, 0.5 * force / (WIDTH * T)))
    strain_at_peak = max(curve, key=lambda p: p[1])[0]
    if (curve[-1][1] < 0.5 * max(s for _, s in curve) and strain > strain_at_peak + 0.005) or strain > 0.05:
        break
    if law.unstable:
        raise RuntimeError("the UCS run went unstable")

peak_stress = max(s for _, s in curve)
lo, hi = (next(p for p in curve if p[1] >= f * peak_stress) for f in (0.1, 0.5))
young = (hi[1] - lo[1]) / (hi[0] - lo[0])
result = output.comparison(peak_stress, LAB_UCS, "Pa")
output.write_summary(table.out, output.table_inputs(table), **result, ucs=peak_stress, young_modulus=young,
                     lab_ucs_range=[45e3, 65e3], discs=len(ids), bonds=bonds,
                     tensile_breaks=law.breakMode.count(2), shear_breaks=law.breakMode.count(3), steps=O.iter)
fig, ax = output.figure("axial strain (%)", "axial stress (kPa)", f"UCS, Table 5-1 test {table.test}")
ax.plot([100 * e for e, _ in curve], [s / 1e3 for _, s in curve])
ax.axhspan(45, 65, color="0.9", label="laboratory UCS 45-65 kPa")
ax.legend()
output.save_figure(fig, table.out, "stress_strain")
print(f"UCS {peak_stress / 1e3:.1f} kPa (lab mean 56.7, range 45-65), E {young / 1e6:.2f} MPa, "
      f"{law.breakMode.count(2)} tensile / {law.breakMode.count(3)} shear breaks, {len(ids)} discs")
