"""Reading runs back: a run folder's summary.json and ParaView series, and the summaries of many runs."""
from __future__ import annotations

import fnmatch
import glob
import json
import os
from typing import Any, Sequence


def read_run(out: str) -> dict[str, Any]:
    """A finished run in ``out``: its summary (``summary.json``) and where its pictures and
    ParaView series are (``pictures``: PNG paths; ``paraview``: .pvd paths by kind)."""
    path = os.path.join(out, "summary.json")
    if not os.path.exists(path):
        raise FileNotFoundError(f"{out} holds no summary.json: the run has not finished (run it again to resume it)")
    with open(path) as f:
        summary = json.load(f)
    series = sorted(glob.glob(os.path.join(out, "paraview", "*.pvd")))
    return {"summary": summary, "pictures": sorted(glob.glob(os.path.join(out, "*.png"))),
            "paraview": {os.path.splitext(os.path.basename(p))[0]: p for p in series}}


def summary_of(out: str) -> dict[str, Any]:
    """``<out>/summary.json``, or an empty dict while the run has not written one (or left it unreadable)."""
    try:
        with open(os.path.join(out, "summary.json")) as f:
            return json.load(f)
    except (OSError, ValueError):
        return {}


def read_summaries(folder: str, patterns: Sequence[str] = ("*",)) -> dict[str, dict]:
    """Summaries by run name (the out folder's name) of the runs in ``folder`` whose name matches
    one of the shell-style ``patterns``."""
    runs = {}
    for path in sorted(glob.glob(os.path.join(folder, "*", "summary.json"))):
        name = os.path.basename(os.path.dirname(path))
        if any(fnmatch.fnmatchcase(name, pattern) for pattern in patterns):
            with open(path) as f:
                runs[name] = json.load(f)
    return runs
