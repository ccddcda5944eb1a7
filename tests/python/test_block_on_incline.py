"""examples/verification/block_on_incline.py: a bonded block on a smooth joint (thesis §4.4)."""
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
