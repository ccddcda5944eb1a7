"""Galandrood mine (thesis §5.4.2): a 16.5 m slope of 0.3 m layers dipping 39° into it (Fig 5-44),
discs and bonds of Table 5-14, smooth joints of Table 5-15. Built, bonded and settled, jointed, run
to rest or failure; if it stands, the factor at which the first bond would break (the bonds'
strengths divided, Table 5-16's way) and a trial at the thesis' factor 1.62, from the standing scene.

    ./yade -x -n -j1 examples/field/galandrood.py

Our reconstruction of the section: examples/params.py (GALANDROOD_SHAPE), docs/cases/galandrood.md;
the same slope by limit equilibrium: examples/field/galandrood_lem.py.
"""
import dataclasses
import os

from yade import O
from yade.utils import readParamsFromTable

from examples import params
from toppling.analyse import failure
from toppling.io import output, tilt_report
from toppling.load import strength_reduction, tilting
from toppling.models import equivalent_slope, tilting_table

readParamsFromTable(**params.GALANDROOD, out="results/galandrood/base", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

criteria = tilting.StageCriteria(table.chunk, table.rest_speed, table.fail_displacement, table.max_stage_time,
                                 table.fail_columns)  # each checks its parameters before anything is built
joint = tilting_table.JointMaterial(table.joint_kn, table.joint_friction, table.joint_ks)
slope = equivalent_slope.EquivalentSlope(
    shape=equivalent_slope.SlopeShape(**{**params.GALANDROOD_SHAPE, "columns": table.columns}), rock=params.TABLE_5_14,
    main=joint, base=joint, base_joints=[], joints_into_foundation=bool(table.joints_into_foundation),
    joint_gap=table.joint_gap, bond_gap=table.bond_gap,
    rmin=table.rmin, rmax=table.rmax, porosity=table.porosity, seed=table.seed, timestep_safety=table.timestep_safety,
    damping=table.damping)
protocol = equivalent_slope.protocol(table, slope)
run = tilting_table.start(slope, protocol, criteria, output.table_inputs(table), table.out, table.resume)
run.run()
thesis = dict(failure_tilt_deg=None, phi_deg=[], stable_unreduced=params.GALANDROOD_RESULT["stable_unreduced"],
              dem_factor_of_safety=params.GALANDROOD_RESULT["fails_at_factor"],
              bftop_factor_of_safety=params.FIG_5_44_RESULT["factor_of_safety"],
              monitoring_points=[failure.column_label(k) for k in (1, 2, 5, 10, 20, 40)])
tilt_report.report(run, table.out, thesis, "Galandrood")

if run.failure_tilt is None and not run.state.get("stopped"):  # it stands: how far are its bonds from breaking?
    standing = os.path.join(table.out, "standing.yade.gz")
    O.save(standing)
    reduction = strength_reduction.Reduction(friction="angle", scope="bonds")  # Table 5-16: 8.1° / 1.62 = 5°
    first = strength_reduction.first_break_factor(reduction)
    search = strength_reduction.Search(standing, run.state["watched"], criteria, reduction)
    trial = search.trial(table.reduction_factor)
    output.add_to_summary(table.out, first_break_factor=first, reduced_trial=dataclasses.asdict(trial))
    print(f"Galandrood stands; the first bond would break at F = {first:.1f}; at F = {table.reduction_factor:g} "
          f"(the thesis' failing factor) it {'fails' if trial.failed else 'stands'}: moved "
          f"{1e3 * trial.displacement:.1f} mm, {trial.breaks} bonds broken, {trial.time:.2f} s")
