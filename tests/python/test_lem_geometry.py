"""toppling.lem.geometry: the blocks and columns a slope is cut into, against Hoek and Bray's
discretisation and plane geometry."""
import math

import pytest

from toppling.lem import goodman_bray as gb
from toppling.lem.geometry import SlopeGeometry

# Hoek and Bray's example (test_lem_goodman_bray): a2 = 5 m needs ψs = 30° - atan(0.5), b = 1 m needs θ = atan(0.1)
EXAMPLE = SlopeGeometry(height=92.5, face_deg=56.6, top_deg=30 - math.degrees(math.atan(0.5)), joint_dip_deg=60.0,
                        failure_plane_deg=math.degrees(math.atan(0.1)), spacing=10.0)


def test_the_example_slope_gives_the_published_blocks():
    blocks = EXAMPLE.blocks(unit_weight=25.0)
    assert blocks.crest == 10 and len(blocks.heights) == 16
    assert blocks.a1 == pytest.approx(5.0, abs=0.01) and blocks.a2 == pytest.approx(5.0)
    published = [4.0 * n for n in range(1, 11)] + [40.0 - 6.0 * k for k in range(1, 7)]
    assert blocks.heights == pytest.approx(published, abs=0.1)
    assert gb.limiting_friction(blocks) == pytest.approx(38.15, abs=0.05)


def test_side_lengths_below_the_crest_step_by_a1_minus_b():
    """Below the crest a joint meets the face at a right angle to the joints' normal, so side j
    is j (Δx tan(ψf - ψp) - Δx tan θ) long; the first side that starts above the surface is 0."""
    sides = EXAMPLE.side_lengths()
    step = 10.0 * (math.tan(math.radians(56.6 - 30.0)) - 0.1)
    assert sides[:10] == pytest.approx([j * step for j in range(10)], rel=1e-9)
    assert sides[0] == sides[-1] == 0 and all(s > 0 for s in sides[1:-1])


def test_a_models_slope_shape_measures_its_face_from_behind():
    shape = dict(height=0.475, joint_dip_deg=55.0, face_deg=98.0, top_deg=8.0, spacing=0.047)
    slope = SlopeGeometry.from_slope_shape(15.0, **shape)
    assert slope.face_deg == 82.0 and slope.base_dip_deg == 35.0


@pytest.mark.parametrize("field, value, message", [
    ("face_deg", 35.0, r"face_deg = 35.0 is invalid: it must be in \(35.7106, 90\)"),
    ("joint_dip_deg", 0.0, r"joint_dip_deg = 0.0 is invalid: it must be in \(0, 90\)"),
    ("spacing", -1.0, r"spacing = -1.0 is invalid"),
    ("top_deg", 31.0, r"top_deg = 31.0 is invalid: it must be in \[0, 30\)"),
])
def test_bad_slopes_are_refused_naming_the_parameter(field, value, message):
    fields = dict(height=92.5, face_deg=56.6, top_deg=3.4, joint_dip_deg=60.0, failure_plane_deg=5.7106, spacing=10.0)
    with pytest.raises(ValueError, match=message):
        SlopeGeometry(**{**fields, field: value})
