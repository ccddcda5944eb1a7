"""A single bond loaded to failure breaks at the load its criteria predict, in the right mode
(examples/verification/bond_strength.py)."""
import math

import pytest
from conftest import run_example

TENSILE, COHESION = 1e6, 1e6


@pytest.mark.parametrize("load, compression, mode", [
    ("pull", 0.0, "tension"),
    ("bend", 0.0, "tension"),
    ("shear", 0.0, "shear"),
    ("shear", 2e6, "shear"),  # friction term: strength (c + sigma tan 30°) A = 2.15 c A
])
def test_bond_breaks_at_its_strength_in_the_right_mode(tmp_path, load, compression, mode):
    s = run_example("examples/verification/bond_strength.py", tmp_path, load=load, compression=compression,
                    tensile=TENSILE, cohesion=COHESION)
    assert s["mode"] == mode
    assert s["rel_error"] < 0.01
    if load == "shear":  # the reference used the measured normal stress: check it against the input too
        assert s["sigma_at_break"] == pytest.approx(compression, abs=0.01 * COHESION)
        area = s["reference"] / (COHESION + s["sigma_at_break"] * math.tan(math.radians(30)))
        assert s["measured"] == pytest.approx((COHESION + compression * math.tan(math.radians(30))) * area, rel=0.01)
