"""How the columns gone in each run's failing stage moved: as a whole, or by a part breaking off.

    python3 scripts/gone_columns.py results/tilting_table/<run> [...]

From a run's checkpoint.json and its ParaView snapshots (one at the start tilt, one after every
stage), for the first failing stage: per gone column, the mean and the median displacement of
its watched top discs from the stage's start to the failure, and how many of them moved more
than fail_displacement; then whether the medians alone fail the stage at that moment
(fail_columns past it).
A column that toppled off moves with most of its discs; a mean past fail_displacement with a
median far below it is a part (a corner of the top) that broke off and fell, and the column stood
(docs/tilting_table.md, "A column top's corner falling off").
"""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bond_stress_history import snapshots  # noqa: E402
from onset_failure import at_time, disc_arrays  # noqa: E402


def report(out: str) -> list[str]:
    """The lines printed for the run folder ``out``."""
    name = os.path.basename(out.rstrip("/"))
    if not os.path.exists(os.path.join(out, "checkpoint.json")):
        return [f"{name}: no checkpoint yet"]
    with open(os.path.join(out, "checkpoint.json")) as f:
        state = json.load(f)
    stages = state["stages"]
    failed = next((k for k, s in enumerate(stages) if s["outcome"] == "failed"), None)
    if failed is None:
        return [f"{name}: no stage failed"]
    failed_at = stages[failed]["time"]
    before = [entry for entry in snapshots(out, "discs") if entry[0] < failed_at]
    if not before:  # a run older than the snapshot at the start tilt
        return [f"{name}: failed in its first stage, no snapshot at its start"]
    start, end = disc_arrays(max(before)[1])[0], disc_arrays(at_time(out, "discs", failed_at))[0]
    index = {i: n for n, i in enumerate(state["series"]["ids"])}
    groups = dict(zip(state["watched_columns"], state["watched"]))  # a gone column stays watched after the failure
    limit, needed = state["inputs"]["fail_displacement"], state["inputs"]["fail_columns"]
    lines, past = [f"{name}: fails at {stages[failed]['tilt']:g} deg, fail_displacement {1e3 * limit:g} mm"], 0
    for label in stages[failed]["gone"]:
        rows = [index[i] for i in groups[label]]
        moved = np.linalg.norm(end[rows] - start[rows], axis=1)
        mean = np.linalg.norm(end[rows].mean(axis=0) - start[rows].mean(axis=0))
        median = np.linalg.norm(np.median(end[rows], axis=0) - np.median(start[rows], axis=0))
        past += median > limit
        lines.append(f"  {label}: mean {1e3 * mean:.1f} mm, median {1e3 * median:.1f} mm, "
                     f"{int((moved > limit).sum())} of {len(rows)} discs past fail_displacement")
    verdict = "fails then too" if past >= needed else "does not fail then"
    lines.append(f"  by the medians: {past} of fail_columns {needed} past fail_displacement, the stage {verdict}")
    return lines


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for out in sys.argv[1:]:
        print("\n".join(report(out)))
