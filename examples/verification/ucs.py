"""Numerical UCS test of the block material, thesis §5.2.3 / Table 5-1.

A 4.7 x 10 cm specimen of discs (R 1-2.5 mm), bonded, compressed between platens
(toppling.models.specimen) moving at `velocity` each (0.01 m/s in the thesis). Reported: Young's modulus (secant between 10 % and 50 % of the peak) and the peak
(UCS), against the laboratory UCS of the blocks, 45-65 kPa, mean 56.7 kPa (Amini et al.
2015, quoted in §5.2.3).

Differences from the thesis, stated: porosity 0.18 instead of 0.12 (0.12 needs locked-in
overlap, docs/model.md), bond radius multiplier 1 (not given), bond gap `bond_gap` x Rmin.

    ./yade -x -n examples/verification/ucs.py            # test=1 (Table 5-1 column)
"""
from yade import O
from yade.utils import readParamsFromTable
from yade.wrapper import ParallelBondMat

from examples import params
from toppling.build import engines
from toppling.io import output
from toppling.io.params import check
from toppling.models import specimen

readParamsFromTable(test=1, **params.UCS_TEST, porosity=0.18, bond_gap=0.1, relax_steps=500, seed=1, out="results/ucs",
                    noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

TABLE_5_1, LAB_UCS = params.TABLE_5_1, params.LAB_UCS
(WIDTH, HEIGHT), T = params.UCS_SPECIMEN, 1.0

check(table, test="whole [1, 3]", rmin="(0, inf)", rmax="(0, inf)", velocity="(0, inf)", porosity="(0, 1)",
      bond_gap="[0, inf)", relax_steps="whole [0, inf)", seed="whole [0, inf)")  # test: a Table 5-1 column
rock = ParallelBondMat(thickness=T, **params.TABLE_5_1_COMMON, **TABLE_5_1[table.test])
spec = specimen.build_specimen(WIDTH, HEIGHT, table.rmin, table.rmax, table.porosity, rock, table.relax_steps,
                                  table.bond_gap, table.seed)
curve = specimen.compress(spec, table.velocity)
law = engines.bond_law()
peak_stress = curve.peak
young, poisson = specimen.elastic_constants(curve)
result = output.comparison(peak_stress, LAB_UCS, "Pa")
output.write_summary(table.out, output.table_inputs(table), **result, ucs=peak_stress, young_modulus=young, poisson_ratio=poisson,
                     lab_ucs_range=[45e3, 65e3], discs=len(spec.ids), bonds=spec.bonds,
                     tensile_breaks=law.breakMode.count(2), shear_breaks=law.breakMode.count(3), steps=O.iter)
fig, ax = output.figure("axial strain (%)", "axial stress (kPa)", f"UCS, Table 5-1 test {table.test}")
ax.plot([100 * e for e in curve.axial_strain], [s / 1e3 for s in curve.axial_stress])
ax.axhspan(45, 65, color="0.9", label="laboratory UCS 45-65 kPa")
ax.legend()
output.save_figure(fig, table.out, "stress_strain")
print(f"UCS {peak_stress / 1e3:.1f} kPa (lab mean 56.7, range 45-65), E {young / 1e6:.2f} MPa, "
      f"{law.breakMode.count(2)} tensile / {law.breakMode.count(3)} shear breaks, {len(spec.ids)} discs")
