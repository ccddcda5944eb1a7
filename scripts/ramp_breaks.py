"""The bonds a finished tilting-table run broke before its first stage, told apart: cracks in
the rock, or bonds that held a loose disc (toppling.bonding.rock_breaks), and the tilt at which
the ramp first cracked the rock. Runs older than that count (2026-11-27) warned of every break.

    ./yade -x -n scripts/ramp_breaks.py results/tilting_table/<run> [...] [--write]

Reads each run's checkpoint (the scene keeps every break's time and discs; the ramp's tilt at a
time is read off the run's tilt history). Prints one row per run; ``--write`` adds the count to
the run's summary.json and checkpoint.json, as a run does now, so that the collect script stops
counting a run cracked by debris coming off as cracked.
"""
import json
import os
import sys

import numpy as np

from toppling import monitor, output, tilt_run


def sort_breaks(folder: str) -> tuple[dict, dict]:
    """The run's checkpoint state and its breaks before the stages, sorted."""
    state = monitor.Checkpoint(folder).load()
    times, tilts = np.array([(t, tilt) for t, tilt, _ in state["energy"]]).T
    before = tilt_run.sort_breaks_before_stages(dict(state["breaks_before_stages"]),
                                                lambda t: float(np.interp(t, times, tilts)))
    return state, before


def write(folder: str, state: dict, before: dict) -> None:
    state["breaks_before_stages"] = before
    with open(os.path.join(folder, "checkpoint.json"), "w") as f:
        json.dump(state, f)
    with open(output.summary_path(folder)) as f:
        summary = json.load(f)
    output.write_summary(folder, **{**summary, "breaks_before_stages": before})


def main(folders: list[str], save: bool) -> None:
    print("| run | level: all (loose) | ramp: all (loose) | ramp's first crack (deg) |")
    print("|---|---|---|---|")
    for folder in folders:
        state, before = sort_breaks(folder)
        first = before.get("first_ramp_crack_deg")
        print(f"| {os.path.basename(folder.rstrip('/'))} | {before['level']} ({before['loose']['level']}) | "
              f"{before['ramp']} ({before['loose']['ramp']}) | {'-' if first is None else f'{first:.1f}'} |",
              flush=True)
        if save:
            write(folder, state, before)


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if a != "--write"]
    if not args:
        sys.exit(__doc__)
    main(args, "--write" in sys.argv[1:])
