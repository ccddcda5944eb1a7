"""A study's record: one CSV row per finished run, kept in the repository, so that a study spread
over several machines and sessions loses no run when a machine's results folder goes.

Each study says which figures of a summary its row holds (``row``); the record is read back with
those figures as numbers, and ``missing`` tells a sweep which of a table's lines are still to run.
"""
from __future__ import annotations

import csv
import os
from typing import Any, Callable, Optional, Sequence

from toppling.io.reader import read_summaries
from toppling.run.sweep import batch_table

Row = Callable[[str, dict[str, Any]], dict[str, Any]]


def _number(text: str) -> Optional[float]:
    return float(text) if text != "" else None


def read(path: str, numbers: Sequence[str]) -> dict[str, dict[str, Any]]:
    """The record's rows by run name (column ``run``); the ``numbers`` columns as floats (None
    where empty, or where the record predates the column), the others as text. No file: no rows."""
    if not os.path.exists(path):
        return {}
    with open(path, newline="") as f:
        return {r["run"]: {**r, **{k: _number(r.get(k) or "") for k in numbers}} for r in csv.DictReader(f)}


def update(path: str, folder: str, row: Row, numbers: Sequence[str]) -> dict[str, dict[str, Any]]:
    """The record at ``path`` with a row (``row(name, summary)``, which names its ``run``) for
    every finished run in ``folder`` added or replaced, written back sorted by run."""
    rows = read(path, numbers)
    rows.update({name: row(name, s) for name, s in read_summaries(folder).items()})
    if not rows:
        return {}
    columns = list(dict.fromkeys(k for r in rows.values() for k in r))
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)  # a study's first record
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, columns, lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows[name] for name in sorted(rows))
    return read(path, numbers)


def missing(table_path: str, rows: dict[str, Any]) -> str:
    """The lines of a yade-batch table whose run (its ``out`` folder's name) the record lacks, in
    ``--lines`` form (``3,5,8``), for ``toppling-sweep``."""
    lines = batch_table.read(table_path).lines.values()
    return ",".join(str(line.number) for line in lines
                    if os.path.basename(line.parameters()["out"].rstrip("/")) not in rows)


def commit(summary: dict[str, Any]) -> str:
    """The code a run was made with, as a record cell: its commit, ``+modified`` when the tree
    had uncommitted changes; empty outside git."""
    code = summary.get("code") or {}
    return code.get("commit", "") + ("+modified" if code.get("modified") else "")
