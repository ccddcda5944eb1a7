"""examples/verification/block_on_incline.py: a bonded block on a smooth joint (thesis §4.4)."""
import math

import pytest

from conftest import run_example

COARSE = 0.012  # rmax [m]: a few dozen discs across the block, seconds per run


def test_table_4_6_block_topples(tmp_path):
    s = run_example("examples/verification/block_on_incline.py", tmp_path, b=0.11, h=0.32, alpha=26.0, phi=26.5,
                    rmax=COARSE)
    assert s["mode"] == "topple"


def test_frictionless_smooth_joint_slides_at_g_sin_alpha(tmp_path):
    s = run_example("examples/verification/block_on_incline.py", tmp_path, b=0.2, h=0.1, alpha=15.0, phi=0.0,
                    rmax=COARSE, duration=0.4)
    assert s["mode"] == "slide"
    assert s["acceleration"]["rel_error"] < 0.02


def test_without_smooth_joint_the_coarse_block_interlocks(tmp_path):
    s = run_example("examples/verification/block_on_incline.py", tmp_path, b=0.2, h=0.1, alpha=15.0, phi=0.0,
                    rmax=COARSE, duration=0.4, smooth=0)
    assert s["mode"] == "stable"
    assert abs(s["translation"]) < 0.01 * 0.2


@pytest.mark.parametrize("phi", [5.0, 15.0, 24.0])
def test_in_sagasetas_band_the_block_slides_upright(tmp_path, phi):
    """tan phi <= b/h < tan alpha (b/h 0.5, alpha 30 deg): a rigid block slides without turning
    (Sagaseta 1986), at the sliding block's acceleration g (sin alpha - cos alpha tan phi), from
    the band's foot to its top, where the reaction lies 0.9 Rmax inside the toe."""
    s = run_example("examples/verification/block_on_incline.py", tmp_path, b=0.2, h=0.4, alpha=30.0, phi=phi,
                    rmax=COARSE, duration=0.6)
    assert math.tan(math.radians(phi)) <= 0.5 < math.tan(math.radians(30.0))
    assert s["mode"] == "slide"
    assert abs(s["rotation_deg"]) < 1.0
    assert s["acceleration"]["rel_error"] < 0.05
