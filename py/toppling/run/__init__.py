"""Running a scene: steps in this thread, staged tilting runs, checkpoints that resume, progress lines, monitoring points; running many (sweeps on Dask)."""
