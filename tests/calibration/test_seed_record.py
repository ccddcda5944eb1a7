"""calibration/tilting_table/seed_record.py on a made-up record and on the committed one."""
import csv
import math
import os
import random
from statistics import NormalDist

import pytest
from conftest import REPO, load_script
from toppling.analyse.seeds import within

record = load_script("calibration/tilting_table/seed_record.py")

MADE_UP = record.read_rows("""seed,size,failure_tilt_deg,lower_bound,line,note
1,coarse,30,0,10,
1,"fine, a gap",34,0,20,
2,coarse,40,0,11,
2,"fine, a gap",,0,,stopped: the ramp broke 5 bonds
3,coarse,35,0,12,
3,"fine, a gap",36,0,22,
4,coarse,39,0,13,
4,"fine, a gap",35,0,23,
""".splitlines())
STOPPED = [dict(row, failure_tilt_deg="40", lower_bound="1", note="stood at 38°")
           if (row["seed"], row["size"]) == ("4", "fine, a gap") else row for row in MADE_UP]  # seed 4 fine unfailed


def write_record(path, rows) -> None:
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


FINE, COARSE = [34.0, 36.0, 35.0], [30.0, 40.0, 35.0, 39.0]  # the made-up record's columns
SPREAD = 62 / 3 + 1  # their two sample variances


def test_the_record_is_read_by_column_and_a_seed_not_run_is_left_out():
    assert record.read_record(MADE_UP) == {"coarse": [30.0, 40.0, 35.0, 39.0], "fine, a gap": [34.0, 36.0, 35.0]}


def test_a_seed_stopped_before_it_failed_is_a_lower_bound_kept_apart_from_the_tilts():
    assert record.read_record(STOPPED) == {"coarse": COARSE, "fine, a gap": [34.0, 36.0]}
    bounds = record.read_record(STOPPED, bounds=True)
    assert bounds == {"coarse": [], "fine, a gap": [40.0]}
    assert record.with_bounds(record.read_record(STOPPED), bounds)["fine, a gap"] == [34.0, 36.0, 40.0]


def test_main_prints_the_verdicts_again_with_the_stopped_seeds_at_their_bounds(tmp_path, capsys):
    path = tmp_path / "record.csv"
    write_record(path, STOPPED)
    record.main(str(path))
    out = capsys.readouterr().out
    assert "(fine, a gap 1) at their lower bounds" in out
    assert "| fine, a gap | 2 | 35.0 ± 1.4 |" in out  # without the bound
    assert "| fine, a gap | 3 | 36.7 ± 3.1 |" in out  # with it: a higher mean


def test_the_margin_is_the_distance_from_35_plus_two_standard_errors():
    # mean 36, sample variance 62/3, standard error 2.27
    assert record.margin([30.0, 40.0, 35.0, 39.0]) == pytest.approx(1.0 + 2 * (62 / 3 / 4) ** 0.5)


def test_the_report_gives_each_size_its_verdict_and_the_size_check():
    rows = record.report(record.read_record(MADE_UP))
    assert rows[2] == "| coarse | 4 | 36.0 ± 4.5 | 37 | 1 | +1.0 ± 2.3: undecided | 5.55 |"
    assert rows[3] == "| fine, a gap | 3 | 35.0 ± 1.0 | 35 | 3 | +0.0 ± 0.6: yes | 1.15 |"
    assert rows[-1] == "| fine, a gap − coarse | -1.0 ± 2.3 | undecided | 0% | 59 | 175 |"


def measured_chance_of_yes(difference: float, se: float, draws: int = 20000) -> float:
    """How often toppling.analyse.seeds.within reads "yes" for measured differences drawn about ``difference``."""
    rng = random.Random(4)
    hits = sum(within(rng.gauss(difference, se), se, 2.0) == "yes" for _ in range(draws))
    return hits / draws


@pytest.mark.parametrize("difference, se", [(0.0, 0.6), (-1.1, 0.3), (0.5, 0.5)])
def test_the_chance_of_a_yes_is_how_often_the_size_checks_rule_says_yes(difference, se):
    chance = record.chance_of_yes(difference, se)
    assert 0.05 < chance < 0.99
    assert measured_chance_of_yes(difference, se) == pytest.approx(chance, abs=0.01)  # 3 binomial sd


def test_where_two_standard_errors_fill_the_tolerance_a_zero_difference_never_reads_yes():
    assert record.chance_of_yes(0.0, 1.0) == 0.0
    assert measured_chance_of_yes(0.0, 1.0) == 0.0


def test_the_seeds_for_a_yes_are_the_fewest_that_give_a_zero_difference_its_chance():
    n = record.seeds_for_yes(FINE, COARSE)
    # at a difference of 0 the chance is P(|Z| <= (2 - 2 se) / se): 80 % at se = 2 / (2 + z_0.9)
    se = 2 / (2 + NormalDist().inv_cdf(0.9))
    assert n == math.ceil(SPREAD / se**2) == 59
    assert record.chance_of_yes(0.0, (SPREAD / n) ** 0.5) >= record.YES_CHANCE
    assert record.chance_of_yes(0.0, (SPREAD / (n - 1)) ** 0.5) < record.YES_CHANCE


def test_at_a_measured_difference_the_seeds_give_that_difference_its_chance():
    n = record.seeds_for_yes(FINE, COARSE, -1.0)
    assert n == 175
    assert record.chance_of_yes(-1.0, (SPREAD / n) ** 0.5) >= record.YES_CHANCE
    assert record.chance_of_yes(-1.0, (SPREAD / (n - 1)) ** 0.5) < record.YES_CHANCE


def test_a_measured_difference_at_the_tolerance_needs_no_number_of_seeds():
    assert record.seeds_for_yes([34.0, 36.0], [30.0, 40.0], 2.0) is None


def test_seeds_pair_only_where_both_sizes_failed():
    assert record.read_pairs(MADE_UP) == {"fine, a gap": [(30.0, 34.0), (35.0, 36.0), (39.0, 35.0)]}
    assert record.read_pairs(STOPPED) == {"fine, a gap": [(30.0, 34.0), (35.0, 36.0)]}  # seed 4's bound is out


def test_the_paired_row_is_the_mean_of_the_per_seed_differences():
    # differences 4, 1, -4: mean 1/3, sample variance 49/3, standard error 7/3;
    # correlation 5 / sqrt(122/3 * 2) of the centred tilts (-14/3, 1/3, 13/3) and (-1, 1, 0)
    row = record.paired_row("fine", "coarse", record.read_pairs(MADE_UP)["fine, a gap"])
    assert row == "| fine − coarse | 3 | 0.55 | +0.33 ± 2.33 |"


def test_main_prints_the_paired_difference_after_the_size_check(tmp_path, capsys):
    path = tmp_path / "record.csv"
    write_record(path, MADE_UP)
    record.main(str(path))
    out = capsys.readouterr().out
    assert out.index("| size check |") < out.index("| fine, a gap − coarse | 3 | 0.55 | +0.33 ± 2.33 |")


def test_the_committed_record_lists_seeds_1_to_n_with_a_coarse_tilt_or_bound_for_each():
    with open(os.path.join(REPO, "calibration", "tilting_table", "records", "ideal_seeds.csv"), newline="") as f:
        rows = record.read_rows(f)
    seeds = list(dict.fromkeys(int(row["seed"]) for row in rows))
    assert seeds == list(range(1, len(seeds) + 1))
    tilts, bounds = record.read_record(rows), record.read_record(rows, bounds=True)
    assert len(tilts["R 1–4 mm"]) + len(bounds["R 1–4 mm"]) == len(seeds)
