"""toppling.lem.goodman_bray against Hoek and Bray's worked example (Rock Slope Engineering, 3rd
ed., 1981, §10; repeated in Wyllie and Mah 2004, §9.4.3): a 92.5 m slope cut into sixteen 10 m
blocks, a1 = 5 m, a2 = 5 m, b = 1 m, bases dipping 30°, γ = 25 kN/m³. The published table: blocks
16-14 stable, 13-4 toppling, 3-1 sliding; P(n-1) of blocks 13 … 8: 292.5, 825.7, 1556.0, 2826.7,
3922.1, 4594.8 kN/m; the toe needs no support at φ = 38.15°."""
import json
import math

import pytest

from toppling.lem import __main__ as cli
from toppling.lem import goodman_bray as gb

HEIGHTS = tuple([4.0 * n for n in range(1, 11)] + [40.0 - 6.0 * k for k in range(1, 7)])  # y = n(a1 - b), then - (a2 + b)
EXAMPLE = gb.Blocks(HEIGHTS, width=10.0, base_dip_deg=30.0, a1=5.0, a2=5.0, unit_weight=25.0)


def test_the_published_example_modes_forces_and_limiting_friction():
    result = gb.analyse(EXAMPLE, 38.15)
    assert result.modes == ["sliding"] * 3 + ["toppling"] * 10 + ["stable"] * 3
    published = [292.5, 825.7, 1556.0, 2826.7, 3922.1, 4594.8]  # blocks 13 … 8
    assert [round(result.blocks[n - 1].p_below, 1) for n in range(13, 7, -1)] == published
    assert abs(result.toe_force) < 0.001 * max(b.p_below for b in result.blocks)
    assert gb.limiting_friction(EXAMPLE) == pytest.approx(38.15, abs=0.01)


def test_a_squat_block_pushed_from_above_topples():
    """Blocks 14 and 4 have the same shape (y/Δx = 1.6 < cot 30° = 1.73: neither topples alone);
    block 14 has nothing above it and stands, block 4 is pushed by the toppling blocks above."""
    result = gb.analyse(EXAMPLE, 38.15)
    assert HEIGHTS[13] == HEIGHTS[3] == 16.0
    assert result.blocks[13].mode == "stable" and result.blocks[3].mode == "toppling"


def test_base_forces_balance_and_sliding_blocks_use_the_full_friction():
    for block in gb.analyse(EXAMPLE, 38.15).blocks:
        assert block.normal > 0
        if block.mode == "sliding":
            assert block.shear / block.normal == pytest.approx(math.tan(math.radians(38.15)), rel=1e-9)
        if block.mode == "toppling":
            assert block.shear / block.normal < math.tan(math.radians(38.15))


def test_one_block_on_an_incline_closed_form():
    """A squat block slides when φ < ψp (limiting friction = ψp) and no friction holds a block
    whose weight acts outside its base (y/Δx > cot ψp)."""
    squat = gb.Blocks((1.0,), width=2.0, base_dip_deg=25.0, a1=0.0, a2=0.0, unit_weight=20.0)
    assert gb.limiting_friction(squat) == pytest.approx(25.0, abs=1e-3)
    assert gb.analyse(squat, 20.0).modes == ["sliding"] and gb.analyse(squat, 30.0).modes == ["stable"]
    tall = gb.Blocks((5.0,), width=2.0, base_dip_deg=25.0, a1=0.0, a2=0.0, unit_weight=20.0)
    assert gb.analyse(tall, 60.0).modes == ["toppling"]
    with pytest.raises(ValueError, match="toe needs support at every friction angle below 45"):
        gb.limiting_friction(tall)


def test_factor_of_safety_and_the_toe_support_that_gives_it():
    assert gb.factor_of_safety(EXAMPLE, 38.15) == pytest.approx(1.0, abs=1e-3)
    fs = gb.factor_of_safety(EXAMPLE, 45.0)
    assert fs == pytest.approx(math.tan(math.radians(45)) / math.tan(math.radians(38.15)), rel=1e-3)
    assert gb.toe_support(EXAMPLE, 45.0, fs * 0.99) == 0  # already safer than asked
    needed = gb.toe_support(EXAMPLE, 38.15, 1.5)
    assert needed > 0 and gb.toe_support(EXAMPLE, 38.15, 1.6) > needed


@pytest.mark.parametrize("field, value, message", [
    ("width", -10.0, r"width = -10.0 is invalid: it must be in \(0, inf\)"),
    ("base_dip_deg", 90.0, r"base_dip_deg = 90.0 is invalid: it must be in \(0, 90\)"),
    ("heights", (4.0, -1.0), r"heights\[2\] = -1.0 is invalid"),
    ("crest", 17, r"crest = 17 is invalid: it must be a whole number in \[0, 16\]"),
])
def test_bad_blocks_are_refused_naming_the_parameter(field, value, message):
    fields = dict(heights=HEIGHTS, width=10.0, base_dip_deg=30.0, a1=5.0, a2=5.0, unit_weight=25.0)
    with pytest.raises(ValueError, match=message):
        gb.Blocks(**{**fields, field: value})


def test_command_line_prints_the_result_and_refuses_unknown_keys(tmp_path, capsys):
    inputs = dict(heights=list(HEIGHTS), width=10.0, base_dip_deg=30.0, a1=5.0, a2=5.0, unit_weight=25.0,
                  friction_deg=38.15)
    path = tmp_path / "in.json"
    path.write_text(json.dumps(inputs))
    assert cli.main(["goodman-bray", str(path)]) == 0
    out = json.loads(capsys.readouterr().out)
    assert {"toe_force", "modes", "limiting_friction_deg", "factor_of_safety"} <= set(out)
    assert out["limiting_friction_deg"] == pytest.approx(38.15, abs=0.01) and out["modes"][0] == "sliding"
    path.write_text(json.dumps({**inputs, "widht": 10.0}))
    assert cli.main(["goodman-bray", str(path)]) == 2
    assert "unknown input keys ['widht']" in capsys.readouterr().err
