"""examples/verification/tilt_slide.py: a flat block on a smooth joint slides at atan(mu)."""
import math

import pytest
from conftest import run_example


@pytest.mark.parametrize("mu", [0.2, 0.6])
def test_block_starts_to_slide_within_a_degree_of_atan_mu(tmp_path, mu):
    s = run_example("examples/verification/tilt_slide.py", tmp_path, phi=math.degrees(math.atan(mu)), rmax=0.016)
    assert abs(s["slide_tilt_deg"] - math.degrees(math.atan(mu))) <= 1.0
