"""The end of a sweep: one table of every line's status and summary figures, and the failed lines
with the last line of their logs."""
from __future__ import annotations

import csv
from typing import Any, Optional, Sequence

from toppling.io.reader import summary_of
from toppling.run.sweep.sweep import Planned

MAX_DEFAULT_FIGURES = 6
ROW = ("line", "description", "status", "wall_time", "host", "out", "log", "last_log_line")  # before the figures


def scalars(s: dict[str, Any]) -> dict[str, Any]:
    """A summary's top-level numbers, flags and short strings (the figures a table can show)."""
    return {k: v for k, v in s.items() if k != "inputs" and (isinstance(v, (int, float, bool)) or
                                                            (isinstance(v, str) and len(v) <= 40))}


def rows(planned: Sequence[Planned], results: dict[int, dict[str, Any]]) -> list[dict[str, Any]]:
    """One row per line: number, description, status, wall time, host, out, log and the summary's scalars."""
    table = []
    for p in planned:
        r = results.get(p.line.number, {"status": "not run"})
        table.append({"line": p.line.number, "description": p.line.description, "status": r["status"],
                      "wall_time": r.get("wall_time"), "host": r.get("host"), "out": p.out, "log": p.job["log"],
                      "last_log_line": r.get("last_log_line"), **scalars(summary_of(p.out))})
    return table


def default_figures(table: list[dict[str, Any]]) -> list[str]:
    """The scalar figures every summary has, in the first one's order, at most six."""
    fixed = set(ROW)
    with_summary = [r for r in table if set(r) - fixed]
    if not with_summary:
        return []
    common = [k for k in with_summary[0] if k not in fixed and all(k in r for r in with_summary)]
    return common[:MAX_DEFAULT_FIGURES]


def cell(v: Any) -> str:
    if v is None:
        return "-"
    if isinstance(v, float):
        return f"{v:.4g}"
    return str(v)


def markdown(table: list[dict[str, Any]], figures: Optional[Sequence[str]] = None) -> str:
    figures = default_figures(table) if figures is None else list(figures)
    heads = ["line", "description", "status", "wall (s)"] + figures
    keys = ["line", "description", "status", "wall_time"] + figures
    text = ["| " + " | ".join(heads) + " |", "|" + "---|" * len(heads)]
    text += ["| " + " | ".join(cell(r.get(k)) for k in keys) + " |" for r in table]
    failed = [r for r in table if r["status"] == "failed"]
    if failed:
        text.append("\nfailed:")
        text += [f"  line {r['line']} ({r['description']}): {r['last_log_line']}  [log {r['log']}]" for r in failed]
    return "\n".join(text)


def write_csv(table: list[dict[str, Any]], path: str) -> None:
    columns = list(dict.fromkeys(k for r in table for k in r))
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, columns)
        writer.writeheader()
        writer.writerows(table)
