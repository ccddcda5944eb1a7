"""The verification examples of thesis chapter 4 against their closed forms."""
import math

import pytest
from conftest import run_example


def test_free_fall_impact_velocity_and_bounces(tmp_path):
    s = run_example("examples/verification/free_fall.py", tmp_path)
    assert s["reference"] == pytest.approx(4.4294, abs=1e-4)  # sqrt(2 g h), thesis Table 4-1
    assert s["rel_error"] < 5e-4
    assert s["bounces"] >= 5
    assert s["bounce_height_max_rel_error"] < 0.01


@pytest.mark.parametrize("beta", [0.05, 0.13, 0.5])
def test_restitution_matches_spring_dashpot_closed_form(tmp_path, beta):
    s = run_example("examples/verification/restitution.py", tmp_path, beta=beta)
    assert s["reference"] == pytest.approx(math.exp(-math.pi * beta / math.sqrt(1 - beta**2)))
    assert s["rel_error"] < 0.01


def test_cantilever_tip_deflection(tmp_path):
    s = run_example("examples/verification/cantilever.py", tmp_path)
    assert s["reference"] == pytest.approx(34.7, abs=0.05)  # F L^3/3EI + M L^2/2EI, Table 4-3
    assert s["rel_error"] < 0.01
