"""Output every example writes: ``<out>/summary.json`` and PNG plots."""
from __future__ import annotations

import json
import math
import os
import shutil
import subprocess
from typing import Any, Optional

import matplotlib

matplotlib.use("Agg")  # headless: examples run under `yade -x -n`
import matplotlib.pyplot as plt  # noqa: E402


def code_version() -> Optional[dict[str, Any]]:
    """The commit of the checkout this package runs from, and whether its tracked files differ
    from it; None outside a git checkout. Taken when the run starts (this module's import): a
    checkout updated while a run goes does not change the code the run has loaded."""
    try:
        return {"commit": _git("rev-parse", "HEAD"), "modified": bool(_git("status", "--porcelain", "--untracked-files=no"))}
    except (OSError, subprocess.SubprocessError):
        return None


def _git(*args: str) -> str:
    """A git command's output in the checkout that holds this package."""
    repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
    return subprocess.run(["git", "-C", repo, *args], capture_output=True, text=True, check=True, timeout=10).stdout.strip()


CODE = code_version()


def output_dir(out: str) -> str:
    """Create (if needed) and return the output folder."""
    os.makedirs(out, exist_ok=True)
    return out


def prepare_out(out: str, need: float = 0.0) -> str:
    """Create ``out`` and check, before a run starts, that it can be written and has ``need``
    bytes free: a long run must not end in a traceback at its first write. Returns ``out``."""
    try:
        os.makedirs(out, exist_ok=True)
        probe = os.path.join(out, ".toppling-write-test")
        with open(probe, "w") as f:
            f.write("x")
        os.remove(probe)
    except OSError as e:
        raise OSError(f"out = {out!r} cannot be written ({e.strerror}): choose a folder you can write to") from None
    free = shutil.disk_usage(out).free
    if free < need:
        raise OSError(f"out = {out!r} has {free / 1e6:.1f} MB free and the run needs about {need / 1e6:.0f} MB "
                      "(checkpoints, ParaView series, pictures): free some space or choose another folder")
    return out


def comparison(measured: float, reference: float, unit: str) -> dict[str, Any]:
    """A verification result: measured value against its reference, with relative error."""
    rel = abs(measured - reference) / abs(reference) if reference else math.inf
    return {"measured": measured, "reference": reference, "rel_error": rel, "unit": unit}


def summary_path(out: str) -> str:
    return os.path.join(out, "summary.json")


def write_summary(out: str, inputs: dict[str, Any], **results: Any) -> str:
    """Write ``<out>/summary.json`` with the run's inputs, results and the code that ran them
    (``code``: code_version() when the run started); returns its path."""
    path = summary_path(output_dir(out))
    with open(path, "w") as f:
        json.dump({"inputs": inputs, **results, "code": CODE}, f, indent=2, default=float)
    return path


def add_to_summary(out: str, **results: Any) -> str:
    """Add ``results`` to ``<out>/summary.json`` (written before by write_summary); returns its path."""
    with open(summary_path(out)) as f:
        summary = json.load(f)
    summary.update(results)
    summary.pop("code", None)  # the code that wrote it last
    return write_summary(out, summary.pop("inputs"), **summary)


def discard_summary(out: str) -> None:
    """Remove a previous run's ``<out>/summary.json``, so that a run starting afresh in ``out``
    never leaves it to be read as its own."""
    if os.path.exists(summary_path(out)):
        os.remove(summary_path(out))


def table_inputs(table) -> dict[str, Any]:
    """The parameters of ``yade.params.table`` as a plain dict."""
    return {k: getattr(table, k) for k in dir(table) if not k.startswith("_")}


def save_figure(fig, out: str, name: str) -> str:
    """Save a matplotlib figure as ``<out>/<name>.png`` and close it."""
    path = os.path.join(output_dir(out), name + ".png")
    fig.savefig(path, dpi=120, bbox_inches="tight")
    plt.close(fig)
    return path


def figure(xlabel: str, ylabel: str, title: str = "", size: tuple[float, float] = (6, 4)):
    """A new single-axes figure with labels, ``size`` inches."""
    fig, ax = plt.subplots(figsize=size)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title)
    ax.grid(True, alpha=0.3)
    return fig, ax
