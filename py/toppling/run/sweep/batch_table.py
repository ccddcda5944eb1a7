"""A yade-batch table read as ``yade-batch`` and ``readParamsFromTable`` read it, without YADE.

The format (YADE's ``yade.utils.TableParamReader``): the first non-empty line names the columns;
each further non-empty line is one parameter set, keyed by its line number in the file; ``#``
starts a comment; ``=`` repeats the value of the line above; a column ``description`` names the
line (else the ``!``-marked columns, or all, joined as ``name=value``); columns whose name starts
with ``!`` are not parameters (``!SCRIPT``, ``!THREADS``, ``!OMP_NUM_THREADS``, else environment
variables); a value is a Python expression evaluated with :mod:`math`'s names, ``*`` meaning the
script's default.
"""
from __future__ import annotations

import ast
import json
import math
import os
import re
from dataclasses import dataclass, field
from typing import Any, Optional, Sequence


@dataclass
class Line:
    """One parameter set of a table: its line number, description and raw values by column."""
    number: int
    description: str
    values: dict[str, str]

    def parameters(self) -> dict[str, Any]:
        """The values the script receives (``*``: its default, left out)."""
        return {k: evaluate(v) for k, v in self.values.items()
                if not k.startswith("!") and k != "description" and v != "*"}

    def directives(self) -> dict[str, str]:
        """The ``!`` columns, without their ``!``."""
        return {k[1:]: v for k, v in self.values.items() if k.startswith("!")}


@dataclass
class Table:
    path: str
    lines: dict[int, Line] = field(default_factory=dict)

    def select(self, spec: Optional[str]) -> list[Line]:
        """The lines named by ``spec`` in yade-batch's ``--lines`` form (``3,5-8``: 3, 5, 6, 7 and 8);
        all lines when ``spec`` is None."""
        if spec is None:
            return list(self.lines.values())
        wanted = line_numbers(spec)
        unknown = [n for n in wanted if n not in self.lines]
        if unknown:
            raise ValueError(f"--lines {spec}: {self.path} has no parameter set on line(s) "
                             f"{', '.join(map(str, unknown))}; its lines are {', '.join(map(str, self.lines))}")
        return [self.lines[n] for n in wanted]


def evaluate(text: str) -> Any:
    """A table value as ``readParamsFromTable`` evaluates it."""
    return eval(text, dict(vars(math)))  # noqa: S307 (the user's own table, as YADE reads it)


def line_numbers(spec: str) -> list[int]:
    numbers = []
    for part in spec.split(","):
        if not re.fullmatch(r"\s*\d+\s*(-\s*\d+\s*)?", part):
            raise ValueError(f"--lines {spec}: {part!r} is neither a line number nor a range a-b")
        ends = [int(x) for x in part.split("-")]
        numbers += list(range(ends[0], ends[-1] + 1))
    return numbers


def read(path: str) -> Table:
    """Read a yade-batch table; a malformed line raises ValueError naming the file and the line."""
    with open(path) as f:
        text = [re.sub(r"\s*#.*", "", raw.rstrip("\n")) for raw in f]
    usable = [(i + 1, row.split()) for i, row in enumerate(text) if row.strip()]
    if len(usable) < 2:
        raise ValueError(f"{path}: a table needs a line of column names and at least one parameter set")
    (_, heads), rows = usable[0], usable[1:]
    named = "description" in heads
    shown = [h.rstrip("!") for h in heads if h.endswith("!")] or [h.rstrip("!") for h in heads]
    if not named:
        heads = [h[:-1] if h.endswith("!") else h for h in heads]
    table, previous, seen = Table(path), None, set()
    for number, cells in rows:
        if len(cells) != len(heads):
            raise ValueError(f"{path}:{number}: {len(cells)} values for {len(heads)} columns")
        values = dict(zip(heads, cells))
        for k, v in values.items():
            if v == "=":
                if previous is None:
                    raise ValueError(f"{path}:{number}: '=' in column {k} has no line above to repeat")
                values[k] = previous[k]
        previous = values
        if named:
            description = values["description"]
        else:
            description = ",".join(f"{h}={values[h]}" for h in shown).replace("'", "").replace('"', "")
            if description in seen:
                description += f"__line={number}__"
            seen.add(description)
        table.lines[number] = Line(number, description, values)
    return table


def script_default(script: str, name: str) -> Any:
    """The default the script gives ``name`` in its ``readParamsFromTable(...)`` call (None if it
    gives none, or not as a constant)."""
    with open(script) as f:
        tree = ast.parse(f.read(), script)
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and getattr(node.func, "id", getattr(node.func, "attr", None)) == "readParamsFromTable":
            for keyword in node.keywords:
                if keyword.arg == name:
                    try:
                        return ast.literal_eval(keyword.value)
                    except ValueError:
                        return None
    return None


def outs(lines: Sequence[Line], script_of) -> dict[int, str]:
    """Each line's ``out`` folder (its ``out`` column, else its script's default), refused when
    two lines would write to the same folder."""
    found: dict[int, str] = {}
    for line in lines:
        out = line.parameters().get("out", script_default(script_of(line), "out"))
        if not isinstance(out, str) or not out:
            raise ValueError(f"line {line.number} ({line.description}): no out folder (give the table an "
                             "'out' column, or the script an out=... default in readParamsFromTable)")
        found[line.number] = os.path.normpath(out)
    by_out: dict[str, int] = {}
    for number, out in found.items():
        if out in by_out:
            raise ValueError(f"lines {by_out[out]} and {number} both write to out = {out!r}: "
                             "give each line its own out (an 'out' column)")
        by_out[out] = number
    return found


def same_inputs(line: Line, summary: dict[str, Any]) -> bool:
    """Whether a summary was written by a run of this line's parameters (every value the table
    sets is the one the summary's ``inputs`` hold, compared as JSON holds them)."""
    inputs = summary.get("inputs")
    if not isinstance(inputs, dict):
        return False
    as_json = lambda v: json.loads(json.dumps(v, default=float))  # noqa: E731 (tuples as lists, as stored)
    return all(k in inputs and as_json(v) == inputs[k] for k, v in line.parameters().items())
