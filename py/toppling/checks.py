"""Range checks for what a user sets: a value outside its interval, written as in maths
("[0, 90)", "(0, inf)"; "whole [1, 3]" for a whole number), raises ValueError naming the
parameter and the interval."""
from __future__ import annotations

import math
import numbers


def within(value: float, interval: str) -> bool:
    """Whether ``value`` lies in ``interval``."""
    lo, hi = (float(x) for x in interval[1:-1].split(","))
    above = value > lo if interval[0] == "(" else value >= lo
    below = value < hi if interval[-1] == ")" else value <= hi
    return above and below


def require(name: str, value, interval: str) -> None:
    """Raise ValueError unless ``value`` (the parameter ``name``, as the user set it) is a number
    in ``interval``; an interval written "whole [1, 3]" also needs a whole number."""
    whole = interval.startswith("whole ")
    kind = "a whole number" if whole else "a number"
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or math.isnan(value):
        raise ValueError(f"{name} = {value!r} is invalid: it must be {kind} in {interval.removeprefix('whole ')}")
    if (whole and not float(value).is_integer()) or not within(value, interval.removeprefix("whole ")):
        raise ValueError(f"{name} = {value} is invalid: it must be {'a whole number ' if whole else ''}in "
                         f"{interval.removeprefix('whole ')}")
