"""toppling.checks and toppling.io.params: intervals as written in maths, and the first parameter outside its own named."""
from types import SimpleNamespace

import pytest

from toppling.checks import within
from toppling.io.params import check


def test_open_and_closed_ends_and_infinity():
    assert within(0.0, "[0, 90)") and not within(90.0, "[0, 90)") and not within(0.0, "(0, inf)")
    assert within(4.0, "(0, 4]") and within(1e300, "(0, inf)") and not within(-1e-12, "[0, 1]")


def test_the_first_parameter_outside_its_interval_is_named_with_it():
    table = SimpleNamespace(alpha=30.0, b=-0.1, h=float("nan"))
    check(table, alpha="[0, 90)")
    with pytest.raises(ValueError, match=r"^b = -0.1 is invalid: it must be in \(0, inf\)$"):
        check(table, alpha="[0, 90)", b="(0, inf)")
    with pytest.raises(ValueError, match=r"^h = nan is invalid: it must be a number in \(0, inf\)$"):
        check(table, h="(0, inf)")
