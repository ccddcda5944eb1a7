"""toppling.lem.flexural (Aydan and Kawamoto 1992, thesis eq. 2-4) against beam theory."""
import json
import math

import pytest

from toppling.lem import __main__ as cli
from toppling.lem import flexural
from toppling.lem.geometry import SlopeGeometry

SLOPE = SlopeGeometry(height=16.5, face_deg=81.0, top_deg=32.0, joint_dip_deg=39.0, failure_plane_deg=7.0,
                      spacing=0.3)  # Galandrood's shape (thesis Fig 5-44)
ROCK = flexural.Rock(unit_weight=27e3, tensile_strength=5e6, friction_deg=26.0)


def test_a_lone_column_is_held_exactly_when_its_base_reaches_the_tensile_strength():
    """A column h long, b thick, leaning δ from the horizontal, loaded by its weight only: the
    base's tensile stress is 6 M / b² - N / b with M = T h / 2 (T = W cos δ, N = W sin δ); with
    that stress as the tensile strength it needs no force from below. (I = b³/12: the thesis'
    I = b/12 fails this.)"""
    h, b, dip, gamma = 2.0, 0.3, 60.0, 27e3
    weight = gamma * b * h
    stress = 6 * (weight * math.cos(math.radians(dip)) * h / 2) / b ** 2 - weight * math.sin(math.radians(dip)) / b
    rock = flexural.Rock(gamma, stress, 20.0)
    assert flexural.column_force(0.0, h, h, b, dip, rock) == pytest.approx(0.0, abs=1e-9 * weight)
    assert flexural.column_force(0.0, h, h, b, dip, rock.reduced(1.01)) > 0


def test_a_pull_from_above_is_not_passed_on_and_a_push_is():
    rock = flexural.Rock(27e3, 1e5, 26.0)
    alone = flexural.column_force(0.0, 2.0, 2.0, 0.3, 60.0, rock)
    assert flexural.column_force(-500.0, 2.0, 2.0, 0.3, 60.0, rock) == alone
    assert flexural.column_force(500.0, 2.0, 2.0, 0.3, 60.0, rock) > alone


def test_factor_of_safety_brings_the_toe_force_to_zero():
    assert flexural.toe_force(SLOPE, ROCK) < 0  # Galandrood stands unreduced (thesis §5.4.2)
    fs = flexural.factor_of_safety(SLOPE, ROCK)
    assert fs > 1
    assert abs(flexural.toe_force(SLOPE, ROCK.reduced(fs))) < 1e-3 * abs(flexural.toe_force(SLOPE, ROCK))
    assert flexural.toe_force(SLOPE, ROCK.reduced(fs * 1.01)) > 0


def test_command_line_and_bad_rock(tmp_path, capsys):
    geometry = dict(height=16.5, face_deg=81.0, top_deg=32.0, joint_dip_deg=39.0, failure_plane_deg=7.0, spacing=0.3)
    path = tmp_path / "in.json"
    path.write_text(json.dumps(dict(geometry, unit_weight=27.0, tensile_strength=5000.0, friction_deg=26.0)))
    assert cli.main(["flexural", str(path)]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["stable"] and out["factor_of_safety"] == pytest.approx(flexural.factor_of_safety(SLOPE, ROCK), rel=1e-3)
    with pytest.raises(ValueError, match=r"side_force_at = 1.2 is invalid: it must be in \(0, 1\)"):
        flexural.Rock(27e3, 5e6, 26.0, side_force_at=1.2)


def test_galandrood_by_limit_equilibrium_brackets_bftop():
    """examples/field/galandrood_lem.py on BFTOP's input (thesis Fig 5-44): Goodman and Bray (no
    cohesion, no rock strength) find no friction below 45° that holds the toe; Aydan and Kawamoto
    (the columns' 5 MPa) a factor above BFTOP's block-flexure 1.38."""
    import os
    import subprocess
    import sys
    from conftest import REPO
    out = subprocess.run([sys.executable, os.path.join(REPO, "examples", "field", "galandrood_lem.py")],
                         capture_output=True, text=True, check=True, cwd=REPO).stdout
    result = json.loads(out)
    assert result["goodman_bray"]["factor_of_safety"] is None and result["goodman_bray"]["toe_force"] > 0
    assert result["flexural"]["stable"] and result["flexural"]["factor_of_safety"] > result["bftop_thesis"]["factor_of_safety"]


def test_the_breaking_tilt_is_where_beam_theorys_base_tension_reaches_the_strength():
    gamma, width, height, strength = 2900 * 9.81, 0.05, 0.45, 186.6e3
    tilt = flexural.breaking_tilt(gamma, width, height, strength)
    assert flexural.base_tension(gamma, width, height, tilt) == pytest.approx(strength, rel=1e-12)
    assert flexural.base_tension(gamma, width, height, tilt - 0.1) < strength
    with pytest.raises(ValueError, match="strength"):
        flexural.breaking_tilt(gamma, width, height, 1e9)
