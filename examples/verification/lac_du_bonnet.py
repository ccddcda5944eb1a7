"""Lac du Bonnet granite, unconfined biaxial test with the Table 4-4 micro-parameters (thesis §4.3).

Specimen 62 x 155 mm (the laboratory sample's size, L/D = 2.5, which the thesis says HDPAC
reproduced), discs with D_avg = 0.745 mm and Dmax/Dmin = 1.66 (Rmin 0.280, Rmax 0.465 mm),
HDPAC's column of Table 4-4: Ec = Ebar = 69.9 GPa, kn/ks = kbar n/s = 1.5, lambda = 1,
sigma_bar = 145 MPa, tau_bar = 155 MPa, mu = 0.5, rho = 2630 kg/m3. Platens as
toppling.models.specimen, each at `velocity`; PFC's local damping 0.7 (Potyondy & Cundall 2004
run their compression tests damped, quasi-statically). The thesis ran "< 0.1 MPa" confinement,
negligible against q_u ~ 190 MPa, so this test is unconfined.

Reported next to Table 4-5: E, nu (secant 10-50 % of the peak), q_u; thesis HDPAC 62 GPa,
0.231, 187.5 MPa; PFC2D 70.9 GPa, 0.237, 199.1 MPa. Our packing is looser (porosity
`porosity`, 0.18; PFC2D used 0.16 with locked-in stress, docs/model.md), which lowers E and q_u.

    ./yade -x -j2 -n examples/verification/lac_du_bonnet.py      # full size, ~18k discs, tens of minutes
    ./yade-batch -j1 --lines 3,4 examples/verification/lac_du_bonnet.table examples/verification/lac_du_bonnet.py
                                                               # half and quarter size (scale 0.5, 0.25)
"""
from yade import O
from yade.utils import readParamsFromTable
from yade.wrapper import ParallelBondMat

from examples import params
from toppling.build import engines
from toppling.io import output
from toppling.io.params import check
from toppling.models import specimen

readParamsFromTable(scale=1.0, d_avg=params.LAC_DU_BONNET_DISCS["d_avg"], porosity=0.18, bond_gap=0.1, relax_steps=500, velocity=0.05,
                    local_damping=0.7, seed=1, out="results/lac_du_bonnet", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

D_RATIO = params.LAC_DU_BONNET_DISCS["d_ratio"]
WIDTH, HEIGHT = params.LAC_DU_BONNET_SPECIMEN
THESIS, PFC2D = params.TABLE_4_5["thesis_hdpac"], params.TABLE_4_5["pfc2d"]

check(table, scale="(0, 1]", d_avg="(0, inf)", porosity="(0, 1)", bond_gap="[0, inf)", relax_steps="whole [0, inf)",
      velocity="(0, inf)", local_damping="[0, 1)", seed="whole [0, inf)")
rmin = table.d_avg / (1 + D_RATIO)  # D_avg = (Dmin + Dmax) / 2
rock = ParallelBondMat(**params.TABLE_4_4)
spec = specimen.build_specimen(table.scale * WIDTH, table.scale * HEIGHT, rmin, D_RATIO * rmin, table.porosity,
                                  rock, table.relax_steps, table.bond_gap, table.seed)
curve = specimen.compress(spec, table.velocity, local_damping=table.local_damping)
young, poisson = specimen.elastic_constants(curve)
ours = dict(young_modulus=young, poisson_ratio=poisson, ucs=curve.peak)
law = engines.bond_law()
output.write_summary(table.out, output.table_inputs(table), ours=ours, thesis_hdpac=THESIS, pfc2d=PFC2D,
                     rel_error_vs_thesis={k: ours[k] / THESIS[k] - 1 for k in ours}, discs=len(spec.ids),
                     bonds=spec.bonds, tensile_breaks=law.breakMode.count(2), shear_breaks=law.breakMode.count(3),
                     steps=O.iter)
fig, ax = output.figure("axial strain (%)", "stress (MPa)", "Lac du Bonnet granite, Table 4-4")
ax.plot([100 * e for e in curve.axial_strain], [s / 1e6 for s in curve.axial_stress], label="axial stress")
ax.axhline(THESIS["ucs"] / 1e6, color="k", ls="--", label=f"thesis q_u {THESIS['ucs'] / 1e6:g} MPa")
ax.axhline(PFC2D["ucs"] / 1e6, color="0.5", ls=":", label=f"PFC2D q_u {PFC2D['ucs'] / 1e6:g} MPa")
ax.legend()
output.save_figure(fig, table.out, "stress_strain")
print(f"E {young / 1e9:.1f} GPa (thesis 62, PFC2D 70.9), nu {poisson:.3f} (0.231, 0.237), "
      f"q_u {curve.peak / 1e6:.1f} MPa (187.5, 199.1); {len(spec.ids)} discs, {law.breakMode.count(2)} tensile / "
      f"{law.breakMode.count(3)} shear breaks")
