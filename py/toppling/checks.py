"""Range checks for what a user sets: a value outside its interval, written as in maths
("[0, 90)", "(0, inf)"), raises ValueError naming the parameter and the interval."""
from __future__ import annotations

import math


def within(value: float, interval: str) -> bool:
    """Whether ``value`` lies in ``interval``."""
    lo, hi = (float(x) for x in interval[1:-1].split(","))
    above = value > lo if interval[0] == "(" else value >= lo
    below = value < hi if interval[-1] == ")" else value <= hi
    return above and below


def require(name: str, value, interval: str) -> None:
    """Raise ValueError unless ``value`` (the parameter ``name``, as the user set it) is a number in ``interval``."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or math.isnan(value):
        raise ValueError(f"{name} = {value!r} is invalid: it must be a number in {interval}")
    if not within(value, interval):
        raise ValueError(f"{name} = {value} is invalid: it must be in {interval}")
