"""An example's parameters checked before anything is built, by the names the user wrote them
with (``alpha``, ``b``, ``rmax``), not by the names deep inside the library."""
from __future__ import annotations

import math
from typing import Any


def within(value: float, interval: str) -> bool:
    """Whether ``value`` lies in ``interval``, written as in maths: "[0, 90)", "(0, inf)"."""
    lo, hi = (float(x) for x in interval[1:-1].split(","))
    above = value > lo if interval[0] == "(" else value >= lo
    below = value < hi if interval[-1] == ")" else value <= hi
    return above and below


def check(params: Any, **intervals: str) -> None:
    """Raise ValueError naming the first parameter of ``params`` (``yade.params.table``) that is
    not a number in its interval (``alpha="[0, 90)"``), with the interval."""
    for name, interval in intervals.items():
        value = getattr(params, name)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or math.isnan(value):
            raise ValueError(f"{name} = {value!r} is invalid: it must be a number in {interval}")
        if not within(value, interval):
            raise ValueError(f"{name} = {value} is invalid: it must be in {interval}")
