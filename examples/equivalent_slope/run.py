"""Equivalent slope (thesis §5.3): the tilting table's ideal arrangement turned by its failure
tilt (35°) into a slope on a rock foundation, settled bonded, jointed, then left to stand or
topple under gravity.

The defaults are the base model (examples/params.py, EQUIVALENT_SLOPE); the reconstruction of
the geometry: toppling.models.equivalent_slope and docs/cases/equivalent_slope.md. Running the
same command again resumes a stopped run; with ``settled_dir`` runs of the same rock (packing,
strengths, settling) that differ only in their joints or laws settle it once.

    ./yade -x -n -j1 examples/equivalent_slope/run.py
"""
from yade.utils import readParamsFromTable

from examples import params
from toppling.io import output, tilt_report
from toppling.load import tilting
from toppling.models import equivalent_slope, tilting_table
from toppling.run import tilt_run

readParamsFromTable(**params.EQUIVALENT_SLOPE, out="results/equivalent_slope/base", noTableOk=True)
from yade.params import table  # noqa: E402  (filled by readParamsFromTable)

criteria = tilting.StageCriteria(table.chunk, table.rest_speed, table.fail_displacement, table.max_stage_time,
                                 table.fail_columns, table.rest_window)  # each checks its parameters before anything is built
slope = equivalent_slope.from_params(table, params)
protocol = equivalent_slope.protocol(table, slope)
inputs = output.table_inputs(table)
store = tilt_run.settled_store(table.settled_dir, inputs, equivalent_slope.JOINT_INPUTS)
run = tilting_table.start(slope, protocol, criteria, inputs, table.out, table.resume, table.model, store)
run.run()
tilt_report.report(run, table.out, params.EQUIVALENT_SLOPE_RESULTS, "equivalent slope")
