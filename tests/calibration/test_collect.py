"""calibration/tilting_table/collect.py on made-up summaries: the particle-size check, the seed spread, the table."""
import json
import math

import pytest
from conftest import load_script

collect = load_script("calibration/tilting_table/collect.py")


def summary(rmax: float, tilt, phi: list, strength: float = 130e3, arrangement: str = "ideal", **numerics) -> dict:
    inputs = {"arrangement": arrangement, "rmin": rmax / 4, "rmax": rmax, "bond_tensile_strength": strength,
              "main_joint_friction": 0.0, "base_joint_friction": 0.0, **numerics}
    return {"inputs": inputs, "failure_tilt_deg": tilt, "phi_deg": phi,
            "thesis": {"failure_tilt_deg": 35 if arrangement == "ideal" else 19}}


def test_each_packing_is_compared_with_the_next_coarser_of_the_same_model():
    runs = {"coarse": summary(0.008, 34.0, [16.0]), "fine": summary(0.0025, 36.0, [14.5]),
            "medium": summary(0.004, 37.0, [16.0]), "other_model": summary(0.002, 20.0, [30.0], strength=100e3),
            "stands": {**summary(0.001, None, []), "stable_up_to_deg": 37.0}}
    lines = sorted(collect.size_check(runs))
    assert lines == ["| fine vs medium | 1.05 vs 1.05 | -1.0 | -1.5 | yes |",
                     "| medium vs coarse | 1.05 vs 1.05 | +3.0 | 0.0 | no |",
                     "| stands vs fine | 1.05 vs 1.05 | stands to 37.0 vs 36.0 | - | - |"]  # may fail at 38


def test_a_packing_that_stands_beyond_the_tolerance_fails_the_check_and_two_that_stand_say_nothing():
    runs = {"coarse": summary(0.004, 40.0, [15.0]), "fine": {**summary(0.0025, None, []), "stable_up_to_deg": 50.0},
            "coarse_s2": {**summary(0.004, None, [], seed=2), "stable_up_to_deg": 44.0},
            "fine_s2": {**summary(0.0025, None, [], seed=2), "stable_up_to_deg": 44.0}}
    assert collect.size_check(runs) == ["| fine vs coarse | 1.05 vs 1.05 | stands to 50.0 vs 40.0 | - | no |"]


def test_a_bond_gap_in_proportion_to_the_mean_radius_is_compared_at_the_same_bond_density():
    runs = {"coarse": summary(0.004, 40.0, [15.0], bond_gap=0.0), "coarse_gap": summary(0.004, 30.0, [5.0], bond_gap=0.7e-3),
            "fine_dense": summary(0.0025, 41.0, [14.0], bond_gap=1.05e-3 * 3.125 / 5)}  # (rmin + rmax) 5 and 3.125 mm
    assert collect.size_check(runs) == ["| fine_dense vs coarse | 0.65625 vs 1.05 | +1.0 | -1.0 | yes |"]


def test_a_different_number_of_surfaces_fails_the_check():
    runs = {"coarse": summary(0.008, 19.0, [24.0], arrangement="random"),
            "fine": summary(0.004, 19.0, [14.0, 24.0], arrangement="random")}
    assert collect.size_check(runs) == ["| fine vs coarse | 1.05 vs 1.05 | +0.0 | 2 vs 1 surfaces | no |"]


def test_a_model_with_shrunk_overlaps_is_compared_only_with_its_own_kind():
    runs = {"coarse": summary(0.008, 34.0, [16.0]), "fine_shrunk": summary(0.004, 38.0, [12.0], shrink_overlaps=1),
            "coarse_shrunk": summary(0.008, 37.0, [12.5], shrink_overlaps=1), "fine_old": summary(0.004, 33.0, [15.0], shrink_overlaps=0)}
    assert sorted(collect.size_check(runs)) == ["| fine_old vs coarse | 1.05 vs 1.05 | -1.0 | -1.0 | yes |",
                                                "| fine_shrunk vs coarse_shrunk | 1.05 vs 1.05 | +1.0 | -0.5 | yes |"]


def test_a_finer_packing_is_compared_with_the_coarse_run_of_its_own_time_step():
    runs = {"coarse": summary(0.008, 34.0, [16.0]), "coarse_fast": summary(0.008, 30.0, [10.0], timestep_safety=0.8),
            "fine_fast": summary(0.004, 31.0, [11.0], timestep_safety=0.8)}
    assert collect.size_check(runs) == ["| fine_fast vs coarse_fast | 1.05 vs 1.05 | +1.0 | 1.0 | yes |"]


def test_a_finer_packing_with_softened_joints_is_compared_with_the_coarse_run_of_the_same_joints():
    runs = {"coarse": summary(0.008, 32.0, [18.5], timestep_safety=0.8),
            "coarse_soft": summary(0.008, 30.0, [12.0], timestep_safety=0.8, joint_stiffness_scale=0.01),
            "fine_soft": summary(0.004, 31.0, [13.0], timestep_safety=0.8, joint_stiffness_scale=0.01)}
    assert collect.size_check(runs) == ["| fine_soft vs coarse_soft | 1.05 vs 1.05 | +1.0 | 1.0 | yes |"]


def test_softened_joints_are_compared_with_the_same_run_at_table_stiffness():
    def run(tilt, phi, steps, wall, out, **numerics):
        return {**summary(0.008, tilt, phi, out=out, **numerics), "steps": steps, "simulated_time": 2.0, "wall_time": wall}
    runs = {"stiff": run(32.0, [18.5], 1000000, 560.0, "a"),
            "soft": run(32.0, [17.3], 125000, 80.0, "b", joint_stiffness_scale=0.01),
            "soft_seed2": run(38.0, [17.6], 125000, 80.0, "c", joint_stiffness_scale=0.01, seed=2)}
    assert collect.joint_stiffness_check(runs) == ["| soft vs stiff | 0.01 | +0.0 | -1.2 | 8.0 | 7.0 |"]


def test_seeds_give_the_spread_of_one_model_and_a_finer_packing_meets_its_own_seed():
    runs = {"s1": summary(0.008, 32.0, [8.1]), "s2": summary(0.008, 34.0, [18.5], seed=2),
            "s3": summary(0.008, 32.0, [12.0], seed=3), "fine_s2": summary(0.004, 33.0, [17.0], seed=2),
            "alone": summary(0.004, 30.0, [10.0], strength=100e3)}
    assert collect.seed_spread(runs) == ["| ideal 130 kPa R 2–8 mm, safety 0.5 | 1, 2, 3 | 32.0–34.0 | 32.7 ± 1.2 | 3 of 3 | -2.3 ± 0.7: undecided | 12.9 ± 5.3 (8.1–18.5) |"]
    assert collect.size_check(runs) == ["| fine_s2 vs s2 | 1.05 vs 1.05 | -1.0 | -1.5 | yes |"]


def test_a_finer_packing_is_not_paired_with_another_seeds_coarse_packing():
    runs = {"coarse_s2": summary(0.004, 24.0, [15.3], seed=2), "fine_s1": summary(0.0025, 30.0, [12.9])}
    assert collect.size_check(runs) == []


def test_a_seed_that_stands_counts_outside_the_target_and_outside_the_figures():
    runs = {"s1": summary(0.004, 36.0, [17.0]), "s2": summary(0.004, 30.0, [14.4], seed=2),
            "s3": {**summary(0.004, None, [], seed=3), "stable_up_to_deg": 44.0}}
    assert collect.seed_spread(runs) == ["| ideal 130 kPa R 1–4 mm, safety 0.5 | 1, 2, 3 | 30.0–36.0 | 33.0 ± 4.2 | "
                                         "1 of 3 (1 stood) | -2.0 ± 3.0: undecided (2 draws) | 15.7 ± 1.8 (14.4–17.0) |"]


def test_a_failure_by_the_stage_time_limit_is_marked_in_the_table(tmp_path, capsys):
    run = summary(0.008, 21.0, [31.7], arrangement="random")
    run.update(stages=[{"tilt": 20.0, "outcome": "equilibrium"},
                       {"tilt": 21.0, "outcome": "failed", "failed_by": "max_stage_time"}],
               thesis={"failure_tilt_deg": 19, "phi_deg": [14, 24]}, s_over_h=0.69, t_over_h=0.45,
               tensile_breaks=6, shear_breaks=0, discs=1469, wall_time=5561.0)
    (tmp_path / "random_step1").mkdir()
    (tmp_path / "random_step1" / "summary.json").write_text(json.dumps(run))
    collect.main(str(tmp_path))
    row = capsys.readouterr().out.splitlines()[2]
    assert row.startswith("| random_step1 | random |") and "| 20.0 | 21.0 (time limit) | 19.0 | 31.7 | 14.0, 24.0 |" in row


def test_failures_that_came_to_rest_are_named_beside_the_slopes(tmp_path, capsys):
    run = summary(0.004, 27.0, [20.0], arrangement="random", arrest_time=2.0)
    run.update(stages=[{"tilt": 17.0, "outcome": "equilibrium"}, {"tilt": 19.0, "outcome": "failed"},
                       {"tilt": 21.0, "outcome": "failed"}, {"tilt": 23.0, "outcome": "equilibrium"},
                       {"tilt": 25.0, "outcome": "equilibrium"}, {"tilt": 27.0, "outcome": "failed"}],
               arrested_failures=[{"tilt": 19.0}, {"tilt": 21.0}], thesis={"failure_tilt_deg": 19, "phi_deg": [14, 24]},
               s_over_h=0.5, t_over_h=0.4, tensile_breaks=60, shear_breaks=2, discs=5955, wall_time=6000.0)
    (tmp_path / "random_arrest").mkdir()
    (tmp_path / "random_arrest" / "summary.json").write_text(json.dumps(run))
    collect.main(str(tmp_path))
    row = capsys.readouterr().out.splitlines()[2]
    assert "arrest_time 2 |" in row and "| 25.0 | 27.0 (came to rest at 19.0, 21.0) | 19.0 |" in row


def test_patterns_keep_only_the_runs_they_name(tmp_path):
    for name in ("ideal_fine", "ideal_coarse", "random_coarse"):
        (tmp_path / name).mkdir()
        (tmp_path / name / "summary.json").write_text(json.dumps(summary(0.004, 30.0, [15.0])))
    assert sorted(collect.read_summaries(str(tmp_path), ["*_coarse", "ideal_f*"])) == ["ideal_coarse", "ideal_fine", "random_coarse"]
    assert list(collect.read_summaries(str(tmp_path), ["random_*"])) == ["random_coarse"]
    assert len(collect.read_summaries(str(tmp_path))) == 3


def test_a_finer_packing_is_compared_with_the_rerun_of_a_coarse_first_stage_failure():
    runs = {"coarse": {**summary(0.004, 26.0, [17.9], seed=2), "failed_in_first_stage": True},
            "coarse_low": {**summary(0.004, 24.0, [15.3], seed=2, start_tilt=20.0), "failed_in_first_stage": False},
            "fine": summary(0.0025, 34.0, [15.1], seed=2)}
    assert collect.size_check(runs) == ["| fine vs coarse_low | 1.05 vs 1.05 | +10.0 | -0.2 | no |"]


def test_a_first_stage_failure_is_an_upper_bound_and_a_rerun_from_lower_replaces_it():
    runs = {"s1": summary(0.004, 36.0, [17.0]), "s2": summary(0.004, 42.0, [14.6], seed=2),
            "s3": {**summary(0.004, 26.0, [14.8], seed=3), "failed_in_first_stage": True},
            "s3_low": {**summary(0.004, 28.0, [2.8], seed=3, start_tilt=16.0), "failed_in_first_stage": False},
            "s4": {**summary(0.004, 26.0, [11.4], seed=4), "failed_in_first_stage": True}}
    assert collect.seed_spread(runs) == ["| ideal 130 kPa R 1–4 mm, safety 0.5 | 1, 2, 3, 4 | 28.0–42.0 | 35.3 ± 7.0 | "
                                         "1 of 4 (at most 26) | +0.3 ± 4.1: undecided | 11.5 ± 7.6 (2.8–17.0) |"]


def test_a_rerun_from_lower_replaces_a_run_the_ramp_cracked_and_a_cracked_rerun_does_not():
    cracked, intact = {"level": 0, "ramp": 1}, {"level": 0, "ramp": 0}
    debris = {"level": 0, "ramp": 2, "loose": {"level": 0, "ramp": 2}}  # bonds that held loose discs: not cracked
    runs = {"s1": summary(0.004, 36.0, [17.0]),
            "s2": {**summary(0.004, 28.0, [4.0], seed=2), "breaks_before_stages": cracked},
            "s2_low": {**summary(0.004, 34.0, [12.0], seed=2, start_tilt=18.0), "breaks_before_stages": debris},
            "s3": {**summary(0.004, 30.0, [9.0], seed=3), "breaks_before_stages": intact},
            "s3_low": {**summary(0.004, 40.0, [15.0], seed=3, start_tilt=18.0), "breaks_before_stages": cracked},
            "s4": {**summary(0.004, 40.0, [20.0], seed=4, start_tilt=26.0), "breaks_before_stages": intact},  # alike
            "s4_low": {**summary(0.004, 38.0, [10.0], seed=4, start_tilt=18.0), "breaks_before_stages": intact}}
    assert collect.seed_spread(runs) == ["| ideal 130 kPa R 1–4 mm, safety 0.5 | 1, 2, 3, 4 | 30.0–38.0 | 34.5 ± 3.4 | "
                                         "3 of 4 | -0.5 ± 1.7: undecided | 12.0 ± 3.6 (9.0–17.0) |"]


def seeds(rmax: float, tilts: list, phis: list, **kw) -> dict[str, dict]:
    return {f"r{rmax}_s{k}": summary(rmax, t, [p], seed=k, **kw) for k, (t, p) in enumerate(zip(tilts, phis), start=1)}


def test_the_size_check_over_seeds_is_decided_by_two_standard_errors_of_the_difference_of_means():
    agree = {**seeds(0.0025, [33.0, 34.0, 35.0], [15.0, 16.0, 14.0]), **seeds(0.004, [34.0, 33.0, 35.0], [15.0, 14.0, 16.0])}
    assert collect.size_over_seeds(agree) == [
        "| ideal 130 kPa R 0.625–2.5 mm, safety 0.5 vs R 1–4 mm | 3 of 3: 34.0 ± 1.0, φ 15.0 ± 1.0 "
        "| 3 of 3: 34.0 ± 1.0, φ 15.0 ± 1.0 | +0.0 ± 0.8 | +0.0 ± 0.8 | +0.0 ± 0.8 | yes |"]
    stronger = {**seeds(0.0025, [42.0, 44.0, 43.0], [15.0, 16.0, 14.0]), **seeds(0.004, [32.0, 34.0, 33.0], [15.0, 14.0, 16.0])}
    assert collect.size_over_seeds(stronger)[0].endswith("| +10.0 ± 0.8 | +0.0 ± 0.8 | +0.0 ± 0.8 | no |")
    scattered = {**seeds(0.0025, [30.0, 40.0, 35.0], [15.0, 16.0, 14.0]), **seeds(0.004, [34.0, 33.0, 35.0], [15.0, 14.0, 16.0])}
    assert collect.size_over_seeds(scattered)[0].endswith("| +1.0 ± 2.9 | +0.0 ± 0.8 | +0.0 ± 0.8 | undecided |")


def test_one_finer_seed_against_several_coarser_is_undecided_and_a_seed_that_stood_is_left_out():
    runs = {**seeds(0.0025, [42.0], [15.0]), **seeds(0.004, [36.0, 36.0, 40.0, 30.0], [17.0, 12.0, 10.9, 14.4]),
            "fine_s2": {**summary(0.0025, None, [], seed=2), "stable_up_to_deg": 44.0}}
    assert collect.size_over_seeds(runs) == [
        "| ideal 130 kPa R 0.625–2.5 mm, safety 0.5 vs R 1–4 mm | 1 of 2, 1 stood or bounded: 42.0, φ 15.0 "
        "| 4 of 4: 35.5 ± 4.1, φ 13.6 ± 2.7 | +6.5 | +1.4 | +1.4 | undecided (1 vs 4 seeds) |"]
    assert collect.size_over_seeds({**seeds(0.0025, [42.0], [15.0]), **seeds(0.004, [36.0], [17.0])}) == []


def test_seed_means_are_compared_at_the_same_bond_gap_and_at_the_same_bond_density():
    coarse = seeds(0.004, [34.0, 24.0, 28.0], [13.7, 15.3, 16.2])
    fine_table_gap = seeds(0.0025, [36.0, 34.0, 32.0], [15.6, 15.1, 1.9])
    # R 0.625-2.5 mm bonds as many neighbours per disc as R 1-4 mm at 1.05 mm with 1.05 * 3.125 / 5 mm
    fine_dense = seeds(0.0025, [30.0, 34.0, 28.0], [12.9, 16.3, 15.3], bond_gap=0.65625e-3)
    rows = collect.size_over_seeds({**coarse, **{f"t{k}": s for k, s in fine_table_gap.items()}, **fine_dense})
    assert len(rows) == 2
    assert rows[0].startswith("| ideal 130 kPa R 0.625–2.5 mm, safety 0.5 vs R 1–4 mm |")
    assert rows[0].endswith("| +5.3 ± 3.1 | -4.2 ± 4.5 | -4.2 ± 4.5 | undecided |")
    assert "bond gap 0.65625 mm" in rows[1] and "vs R 1–4 mm, bond gap 1.05 mm |" in rows[1]
    assert rows[1].endswith("| +2.0 ± 3.4 | -0.2 ± 1.2 | -0.2 ± 1.2 | undecided |")


def test_a_failure_tilt_within_tolerance_with_an_undecided_phi_is_undecided():
    runs = {**seeds(0.0025, [33.0, 34.0, 35.0], [5.0, 25.0, 15.0]), **seeds(0.004, [34.0, 33.0, 35.0], [15.0, 14.0, 16.0])}
    assert collect.size_over_seeds(runs)[0].endswith("| +0.0 ± 0.8 | +0.0 ± 5.8 | +0.0 ± 5.8 | undecided |")


def test_a_joint_friction_and_joints_between_pieces_name_their_own_seed_group():
    runs = {f"s{seed}{tag}": summary(0.008, tilt, [20.0], arrangement="random", seed=seed, **inputs)
            for tag, inputs, tilts in (("", {}, (15.0, 25.0)),
                                       ("_mu", {"base_joint_friction": 0.23, "joint_pieces": 1}, (17.0, 37.0)))
            for seed, tilt in zip((1, 2), tilts)}
    assert collect.seed_spread(runs) == [
        "| random 130 kPa R 2–8 mm, safety 0.5 | 1, 2 | 15.0–25.0 | 20.0 ± 7.1 | 0 of 2 | +1.0 ± 5.0: undecided (2 draws) "
        "| 20.0 ± 0.0 (20.0–20.0) |",
        "| random 130 kPa R 2–8 mm, safety 0.5, joints between pieces of rock, base joint friction 0.23 | 1, 2 | "
        "17.0–37.0 | 27.0 ± 14.1 | 1 of 2 | +8.0 ± 10.0: undecided (2 draws) | 20.0 ± 0.0 (20.0–20.0) |"]


def test_the_random_arrangement_is_spread_over_packings_and_layouts_where_several_layouts_were_run():
    draws = ((1, 1, 19.0), (2, 1, 15.0), (3, 1, 29.0), (1, 3, 19.0), (1, 2, None))
    runs = {f"s{seed}l{layout}": summary(0.004, tilt, [20.0] if tilt else [], arrangement="random", seed=seed,
                                         layout_seed=layout) for seed, layout, tilt in draws}
    runs["other_model"] = summary(0.004, 40.0, [20.0], arrangement="random", strength=65e3, seed=2)
    assert collect.seed_spread(runs, collect.DRAW) == [
        "| random 130 kPa R 1–4 mm, safety 0.5 | 1/1, 1/2, 1/3, 2/1, 3/1 | 15.0–29.0 | 20.5 ± 6.0 | 2 of 5 (1 stood) | "
        "+1.5 ± 3.0: undecided | 20.0 ± 0.0 (20.0–20.0) |"]
    assert collect.seed_spread(runs) == [  # the packing seeds of layout 1 alone
        "| random 130 kPa R 1–4 mm, safety 0.5 | 1, 2, 3 | 15.0–29.0 | 21.0 ± 7.2 | 1 of 3 | +2.0 ± 4.2: undecided "
        "| 20.0 ± 0.0 (20.0–20.0) |"]


def test_the_mean_over_draws_is_within_the_thesis_tolerance_by_two_standard_errors_or_outside_by_two():
    def spread(tilts):
        runs = seeds(0.004, tilts, [15.0] * len(tilts), arrangement="random")
        return collect.seed_spread(runs)[0].split(" | ")[5]
    assert spread([17.0, 19.0, 21.0, 19.0]) == "+0.0 ± 0.8: yes"  # 0 + 2 x 0.82 <= 3
    assert spread([25.0, 27.0, 29.0, 27.0]) == "+8.0 ± 0.8: no"  # 8 - 2 x 0.82 > 3
    assert spread([15.0, 19.0, 23.0, 19.0]) == "+0.0 ± 1.6: undecided"  # on target, but 0 + 2 x 1.63 > 3


def test_a_stronger_bond_is_measured_on_the_same_packings_and_added_to_the_weaker_mean():
    weak = seeds(0.004, [33.0, 35.0, 34.0, 36.0], [15.0] * 4, strength=85e3)
    strong = seeds(0.004, [35.0, 38.0, 36.0], [15.0] * 3, strength=95e3)
    unpaired = {"strong_s7": summary(0.004, 50.0, [15.0], strength=95e3, seed=7),
                "strong_s4": {**summary(0.004, None, [], strength=95e3, seed=4), "stable_up_to_deg": 45.0},
                "other_model_s1": summary(0.004, 20.0, [15.0], strength=95e3, seed=1, shrink_overlaps=1)}
    rows = collect.strength_pairs({**weak, **{f"x{k}": s for k, s in strong.items()}, **unpaired})
    # shifts 2, 3, 2: 2.33 +- 0.33; 34.5 + 2.33 = 36.83 +- (1.67 / 4 + 0.33^2)^0.5 = 0.73; 1.83 + 1.45 > 3
    assert rows == ["| ideal 85 kPa R 1–4 mm, safety 0.5 | 95 kPa | 1, 2, 3 | +2.3 ± 0.3 | 4: 34.5 ± 1.3 | "
                    "36.8 ± 0.7 | +1.8 ± 0.7: undecided |"]
    assert collect.strength_pairs({**weak, "strong_s1": strong["r0.004_s1"]}) == []  # one pair says nothing


def test_the_size_check_compares_the_overall_phi_of_seeds_whose_points_split_differently():
    """A finer seed whose failure points split into a toe segment along the table and a 45 degree
    one above (overall phi atan(25/42) by hand, fitted from its points as its summary predates
    ``phi_overall_deg``) and two one-surface seeds at that angle, against coarser seeds around
    it: the overall phi agrees, the first surface's would leave the check undecided."""
    dog_leg = [(-k * 0.05, max(0, k - 3) * 0.05) for k in range(8)]
    overall = math.degrees(math.atan(25 / 42))
    split = {**summary(0.0025, 34.0, [0.0, 45.0], seed=1), "failure_points": dog_leg}
    assert collect.overall_phi(split) == pytest.approx(overall)
    assert collect.overall_phi({**split, "phi_overall_deg": 12.0}) == 12.0  # the run's own, where it has one
    fine = {"f1": split, **{f"f{k}": summary(0.0025, 34.0, [overall], seed=k) for k in (2, 3)}}
    coarse = seeds(0.004, [33.0, 34.0, 35.0], [overall - 0.5, overall, overall + 0.5])
    row = collect.size_over_seeds({**fine, **coarse})[0]
    assert row.endswith("| +0.0 ± 0.6 | +0.0 ± 0.3 | -10.3 ± 10.3 | yes |")  # tilt, overall phi, first surface
