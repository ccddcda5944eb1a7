"""Ihlara Valley (thesis §5.4.1): ignimbrite columns 3.5 m wide on Selime tuff, under Hasandagi
ash; the tuff under the front column and half the second weathered (case "weathered") or washed
out (case "eroded"), or neither (case "intact", the control). Built, bonded and settled at rest, jointed, then left to stand or topple.

    ./yade -x -n -j1 examples/field/ihlara.py                        # case 1, weathered
    ./yade-batch -j2 --job-threads 1 examples/field/cases.table examples/field/ihlara.py

The section is our reconstruction (examples/params.py, IHLARA_SECTION; docs/cases/ihlara.md).
"""
from yade.utils import readParamsFromTable

from examples import params
from toppling.io import output, tilt_report
from toppling.load import tilting
from toppling.models import layered_cliff, tilting_table
from toppling.run import tilt_run

readParamsFromTable(**params.IHLARA, out="results/ihlara/weathered", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

cliff = layered_cliff.ihlara_from_params(table, params)  # checks its parameters before anything is built
criteria = tilting.StageCriteria(table.chunk, table.rest_speed, table.fail_displacement, table.max_stage_time,
                                 table.fail_columns)
protocol = tilt_run.TiltProtocol(start_tilt=0.0, step=1.0, max_tilt=0.0, tilt_rate=1.0, stage_rate=0.0,
                                 damping=table.damping, settle_damping=table.settle_damping, arrest_time=0.0,
                                 post_failure_time=table.post_failure_time, checkpoint_every=table.checkpoint_every,
                                 max_wall_time=table.max_wall_time, exact_resume=table.exact_resume)
run = tilting_table.start(cliff, protocol, criteria, output.table_inputs(table), table.out, table.resume)
run.run()
tilt_report.report(run, table.out, dict(failure_tilt_deg=0, phi_deg=[], s_over_h=None, t_over_h=None,
                                        stable_zone_columns=None), f"Ihlara, {table.case}")
