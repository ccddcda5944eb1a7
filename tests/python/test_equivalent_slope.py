"""The equivalent slope's reconstruction (thesis §5.3.1, Table 5-7) and its scene."""
import math
from types import SimpleNamespace

import pytest
from yade import O

from examples import params
from toppling.build import boundary, joints
from toppling.models import equivalent_slope as es

# Table 5-7: D/H of the merged base-joint pair (N2-N1), by N1 (case XVI 2-1 ... case I 17-16)
TABLE_5_7_D_OVER_H = {1: 0.08, 2: 0.15, 3: 0.23, 4: 0.32, 5: 0.40, 6: 0.48, 7: 0.57, 8: 0.65, 9: 0.74, 10: 0.82,
                      11: 0.88, 12: 0.99, 13: 1.07, 14: 1.14, 15: 1.22, 16: 1.31}


def base_model(**changes) -> es.EquivalentSlope:
    return es.from_params(SimpleNamespace(**{**params.EQUIVALENT_SLOPE, **changes}), params)


def test_the_slope_stands_as_high_as_the_thesis_says_with_its_columns_up_to_22():
    model = base_model()
    assert model.shape.tilt_deg == 35.0
    assert model.layout.count == 22  # "negligible deformation in columns 14 to 22"
    assert model.layout.crest_height(35.0) == pytest.approx(0.475, rel=0.01)  # H: the top of the tallest column
    outline = model.shape.outline()
    assert (outline.face_deg, outline.top_deg) == pytest.approx((47.0, 27.0))  # 180 - 98 - 35, 35 - 8


def test_merged_pairs_lie_where_table_5_7_puts_them():
    model = base_model()
    for n1, thesis in TABLE_5_7_D_OVER_H.items():
        assert model.merged_pair_distance(n1) == pytest.approx(thesis, abs=0.02), n1
    tilted_design_plane = 0.047 * (math.cos(math.radians(35)) - math.tan(math.radians(15)) * math.sin(math.radians(35)))
    assert abs(16 * tilted_design_plane / 0.475 - TABLE_5_7_D_OVER_H[16]) > 0.2  # the tilting table's plane would not fit


def test_base_joints_as_data():
    model = base_model(merged_pair=16, base_plane_deg=0.0)
    spans = [(j.first, j.last) for j in model.base_joints]
    assert (16, 17) in spans and (17, 17) not in spans and (15, 15) in spans and len(spans) == 11
    assert [(j.first, j.last, j.height) for j in es.parse_base_joints("1-3;5@0.13")] == [(1, 3, 0.0), (5, 5, 0.13)]
    assert base_model(base_joints="none").base_joints == []
    with pytest.raises(ValueError, match="base_joints = 'x-1'"):
        es.parse_base_joints("x-1")
    with pytest.raises(ValueError, match=r"base_joints\[0\] = columns 3-40"):
        base_model(base_joints="3-40")
    with pytest.raises(ValueError, match="merged_pair"):
        base_model(merged_pair=22)
    with pytest.raises(ValueError, match="face_deg"):
        es.SlopeShape(height=0.475, joint_dip_deg=55, face_deg=150, top_deg=8, spacing=0.047)
    with pytest.raises(ValueError, match="strength_factor"):
        base_model(strength_factor=0)


def test_base_joints_on_a_plane_through_the_toe_cross_the_columns_it_meets_below_their_tops():
    model = base_model(base_plane_deg=15.0)
    rise = math.tan(math.radians(15.0))
    assert [j.first for j in model.base_joints] == [1, 3, 5, 7, 9, 11, 13]  # column 15 is 0.170 m high, the plane 0.183 m
    for j in model.base_joints:
        assert j.height == pytest.approx(rise * (j.first - 0.5) * 0.047)
    pair = base_model(base_plane_deg=15.0, merged_pair=4).base_joints
    assert [(j.first, j.last) for j in pair] == [(1, 1), (3, 3), (4, 5), (7, 7), (9, 9), (11, 11), (13, 13)]
    assert pair[2].height == pytest.approx(rise * 4 * 0.047)  # at the main joint between the pair
    with pytest.raises(ValueError, match="base_plane_deg"):
        base_model(base_plane_deg=90.0)


def test_the_scene_is_bonded_rock_fixed_on_its_foundation_and_jointed_once_settled():
    model = base_model(rmin=0.008, rmax=0.016)
    rise = math.tan(math.radians(model.base_plane_deg))
    layout = model.build()
    toe, foot, back = model.foundation()
    ids = [b.id for b in O.bodies]
    held = [i for i in ids if boundary.is_held(O.bodies[i])]
    assert held and all(O.bodies[i].state.pos[1] < 0.02 for i in held)  # base and right side, none in the columns
    assert joints.blocks() == []  # no joints before the rock has settled
    model.settled()
    system = joints.rock_functor().joints
    sets = list(system.pairSet)
    assert sets.count(0) > 0 and sets.count(1) > 0  # main and base joints cut bonds
    for i, j, s in zip(system.pairId1, system.pairId2, system.pairSet):
        mid = 0.5 * (O.bodies[i].state.pos + O.bodies[j].state.pos)
        if s == 0:  # no main joint reaches into the foundation
            assert mid[1] > -model.rmax
        else:  # the base joints lie on the base plane, each across a blocky column
            k = next(c for c in (layout.column_of(mid[0] + dx) for dx in (0, -model.rmax, model.rmax)) if c % 2 == 1)
            assert abs(mid[1] - rise * (k - 0.5) * layout.width) < model.rmax


def test_without_base_joints_only_the_main_joints_cut_the_rock():
    model = base_model(rmin=0.008, rmax=0.016, base_joints="none")
    model.build()
    model.settled()
    assert set(joints.rock_functor().joints.pairSet) == {0}  # Table 5-8 case II: no base joint at all


def test_main_joints_reach_the_foundations_edge_when_they_run_into_the_foundation():
    through = base_model(joints_into_foundation=1).main_joints()
    toe, foot, back = base_model().foundation()
    on_side = 0
    for (x, y), top in zip(through.segmentStarts, through.segmentEnds):
        # the start lies on the horizontal base (toe to the right side's foot), or beyond the foot on
        # the right side (foot up to the table plane): on the section's edge, never below it
        a, b = (toe, foot) if x >= foot[0] else (foot, back)
        on_side += x < foot[0]
        assert y == pytest.approx(a[1] + (x - a[0]) * (b[1] - a[1]) / (b[0] - a[0]), abs=1e-12) and top[1] > 0
    assert on_side > 0  # the slope's back columns stand over the right side
    assert all(y == 0 for _, y in base_model().main_joints().segmentStarts)


def test_limit_equilibrium_of_the_slope_uses_the_runs_failure_plane(tmp_path):
    """examples/equivalent_slope/lem.py: the thesis' 15° plane without a run, the run's φ and
    friction with one; both methods answer."""
    import importlib
    import json
    lem = importlib.import_module("examples.equivalent_slope.lem")
    alone = lem.main(None)
    assert alone["failure_plane_deg"] == 15 and alone["dem"] is None
    assert alone["flexural"]["factor_of_safety"] > 1 and 0 < alone["goodman_bray"]["limiting_friction_deg"] < 90
    summary = dict(inputs={**params.EQUIVALENT_SLOPE, "main_joint_friction": 0.3}, failed=True, phi_overall_deg=20.0,
                   s_over_h=0.8, t_over_h=0.2, stable_zone_columns=[9, 10])
    (tmp_path / "summary.json").write_text(json.dumps(summary))
    run = lem.main(str(tmp_path))
    assert run["failure_plane_deg"] == 20.0 and run["dem"]["s_over_h"] == 0.8
    assert run["goodman_bray"]["factor_of_safety"] > alone["goodman_bray"]["factor_of_safety"]  # friction 0.3 > 0.12
