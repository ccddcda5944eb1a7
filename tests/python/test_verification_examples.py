"""The verification examples of thesis chapter 4 against their closed forms."""
import math

import pytest
from conftest import run_example, run_yade


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


@pytest.mark.parametrize("example, name, value, valid", [
    ("block_on_incline", "alpha", 95.0, "in [0, 90)"), ("block_on_incline", "b", 0.0, "in (0, inf)"),
    ("block_on_incline", "h", -0.1, "in (0, inf)"), ("block_on_incline", "rmax", 0.0, "in (0, inf)"),
    ("block_on_incline", "phi", 95.0, "in [0, 90)"), ("block_on_incline", "b", "wide", "a number in (0, inf)"),
    ("tilt_slide", "phi", 95.0, "in [4, 86)"), ("tilt_slide", "porosity", 1.5, "in (0, 1)"),
    ("tilt_slide", "step", 0.0, "in (0, 4]")])
def test_an_example_names_the_parameter_the_user_set_wrong(tmp_path, example, name, value, valid):
    proc = run_yade(f"examples/verification/{example}.py", tmp_path, **{name: value})
    shown = repr(value) if isinstance(value, str) else value
    assert proc.returncode != 0
    assert f"{name} = {shown} is invalid: it must be {valid}" in proc.stdout + proc.stderr
    assert not (tmp_path / "out").exists()
