"""Sweeps beyond one machine: the lines of a yade-batch table as tasks of a Dask cluster.

* :mod:`~toppling.run.sweep.batch_table`: the table read as yade-batch reads it; each line's out folder
* :mod:`~toppling.run.sweep.sweep`: the plan (finished lines skipped), the cluster, the tasks and their progress
* :mod:`~toppling.run.sweep.task`: one line run on a worker (sent to the workers by value)
* :mod:`~toppling.run.sweep.report`: the final table of summaries

Command line: ``./toppling-sweep TABLE SCRIPT`` (``python3 -m toppling.run.sweep --help``).
"""
