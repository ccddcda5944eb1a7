"""Tilting-table test (thesis §5.2): columns of jointed rock tilted until they topple.

The defaults are the calibrated ideal model at R 1-4 mm (examples/params.py,
TILTING_TABLE_IDEAL); cases.table holds the thesis' other cases. The reconstruction and the
calibration: docs/cases/tilting_table.md. Running the same command again resumes a stopped run.

    ./yade -x -n -j1 examples/tilting_table/run.py
    ./yade-batch -j2 --lines 7,8,9 examples/tilting_table/cases.table examples/tilting_table/run.py
"""
from yade.utils import readParamsFromTable

from examples import params
from toppling.build import engines
from toppling.io import output, tilt_report
from toppling.load import tilting
from toppling.models import tilting_table
from toppling.run import tilt_run

readParamsFromTable(**params.TILTING_TABLE_IDEAL, out="results/tilting_table/ideal", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

protocol = tilt_run.TiltProtocol.from_params(table)  # each checks its parameters before anything is built
criteria = tilting.StageCriteria(table.chunk, table.rest_speed, table.fail_displacement, table.max_stage_time,
                                 table.fail_columns)
slope = tilting_table.from_params(table, params)
run = tilting_table.start(slope, protocol, criteria, output.table_inputs(table), table.out, table.resume,
                          table.model)
if not table.disc_path:
    engines.set_fast(False)
run.run()
tilt_report.report(run, table.out, params.TILTING_TABLE_RESULTS[table.arrangement], table.arrangement)
