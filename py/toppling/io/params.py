"""An example's parameters checked before anything is built, by the names the user wrote them
with (``alpha``, ``b``, ``rmax``), not by the names deep inside the library."""
from __future__ import annotations

from typing import Any

from toppling.checks import require


def check(params: Any, **intervals: str) -> None:
    """Raise ValueError naming the first parameter of ``params`` (``yade.params.table``) that is
    not a number in its interval (``alpha="[0, 90)"``), with the interval."""
    for name, interval in intervals.items():
        require(name, getattr(params, name), interval)
