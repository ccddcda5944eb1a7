"""calibration/tilting_table/pooled_surfaces.py on made-up summaries (six runs on two surfaces that each alone
falls short of showing), on a made-up and the committed record, and the rule's verdict."""
import json
import math
import os
import re

import numpy as np
import pytest
from conftest import load_script
from toppling.analyse import failure

pooled = load_script("calibration/tilting_table/pooled_surfaces.py")
THESIS = {"failure_tilt_deg": 19.0}


def write_runs(folder, n: int = 6) -> None:
    rng, x = np.random.default_rng(3), -np.arange(1, 11) * 0.05 + 0.025
    t1, t2, xb = math.tan(math.radians(14)), math.tan(math.radians(24)), -0.25
    y = np.where(x > xb, -t1 * x, -t1 * xb - t2 * (x - xb))
    for i in range(n):
        os.makedirs(folder / f"random_{i}")
        points = np.c_[x, y + rng.normal(0, 0.01, len(x))].tolist()
        (folder / f"random_{i}" / "summary.json").write_text(json.dumps({"failure_tilt_deg": 19.0, "thesis": THESIS, "failure_points": points}))
    os.makedirs(folder / "stood")
    (folder / "stood" / "summary.json").write_text(json.dumps({"failure_tilt_deg": None, "thesis": THESIS, "failure_points": []}))


def test_the_runs_of_a_pattern_are_pooled_and_the_cut_found(tmp_path, capsys):
    write_runs(tmp_path)
    pooled.main(pooled.runs_from([str(tmp_path), "random_*", "stood"]))
    out = capsys.readouterr().out.splitlines()
    rows = [line for line in out if line.startswith("| random_")]
    assert len(rows) == 6
    at_cut = [[float(v) for v in row.split("|")[-2].split("/")] for row in rows]
    assert np.mean(at_cut, axis=0) == pytest.approx([14, 24], abs=3)  # each run's lines at the common cut
    assert out[-4].startswith("failure tilt over 6 runs: 19.0 ± 0.0° (19–19°), 6 of 6 within 3°")
    assert out[-3].startswith("6 runs pooled: p = 0.00")
    cut_mm = float(re.search(r"common cut (\d+) mm from the toe", out[-3]).group(1))
    assert 150 < cut_mm < 350  # within a column of the break, 250 mm
    assert out[-3].endswith("the toe shallower in 6")
    assert out[-2].startswith("the thesis' run among these 6: ")


MADE_UP_RECORD = """line,draw,failure_tilt_deg,upper_bound,failure_points_mm
7,"layout 1, packing 2",11,1,29:8 75.5:25
8,"layout 2, packing 1",21,0,30:-4
""".splitlines()


def test_the_record_gives_each_line_its_points_in_the_slope_frame_in_metres():
    runs = pooled.read_record(MADE_UP_RECORD)
    assert list(runs) == ["line 7: layout 1, packing 2", "line 8: layout 2, packing 1"]
    assert runs["line 7: layout 1, packing 2"]["failure_tilt_deg"] == 11
    assert runs["line 7: layout 1, packing 2"]["failed_in_first_stage"]
    assert not runs["line 8: layout 2, packing 1"]["failed_in_first_stage"]
    assert runs["line 7: layout 1, packing 2"]["failure_points"] == pytest.approx(np.array([[-0.029, 0.008], [-0.0755, 0.025]]))
    assert runs["line 8: layout 2, packing 1"]["failure_points"] == pytest.approx(np.array([[-0.030, -0.004]]))


def test_the_failure_tilt_over_the_record_leaves_an_upper_bound_out_of_the_mean_and_counts_it_outside():
    tilts = [("11", 1), ("15", 0), ("21", 0), ("23", 0), ("19", 0)]  # mean 19.5 ± 3.4 over the four, SE 1.7
    record = MADE_UP_RECORD[:1] + [f"{n},draw {n},{t},{bound},30:5" for n, (t, bound) in enumerate(tilts)]
    line = pooled.failure_tilt_line(pooled.read_record(record))
    assert line == ("failure tilt over 4 runs: 19.5 ± 3.4° (15–23°), 2 of 5 within 3° of the thesis' 19°, ≤ 11 left "
                    "out; mean − thesis +0.5 ± 1.7: undecided")


def test_runs_of_models_with_different_thesis_tilts_are_not_pooled_into_one_failure_tilt():
    runs = pooled.read_record(MADE_UP_RECORD)
    runs["line 8: layout 2, packing 1"]["thesis"] = {"failure_tilt_deg": 35.0}
    assert pooled.failure_tilt_line(runs).startswith("failure tilt: not pooled")


def test_the_committed_record_names_each_table_line_once_and_every_row_has_points(capsys):
    runs = pooled.runs_from(["--record"])
    lines = [name.split(":")[0] for name in runs]
    assert len(set(lines)) == len(lines) >= 8
    assert all(s["failure_points"] for s in runs.values())
    pooled.main(runs)
    assert capsys.readouterr().out.splitlines()[-1].startswith(f"the thesis' two surfaces (14° under 24°) over these {len(runs)} runs: ")


def pairs_at(toe_phi, upper_phi):
    """Runs' toe and upper lines at a common cut with these angles."""
    line = lambda phi: failure.Plane(phi, -math.tan(math.radians(phi)), 0.0, (-0.5, 0.0))  # noqa: E731
    return [(line(a), line(b)) for a, b in zip(toe_phi, upper_phi)]


def test_the_rule_needs_the_bend_at_5_percent_and_both_means_inside_their_bands():
    thesis_like = pairs_at([13, 14, 15, 14, 13, 15], [23, 24, 25, 24, 25, 23])
    assert pooled.two_surfaces_verdict(0.01, thesis_like).startswith("met (toe mean − thesis +0.0")
    assert pooled.two_surfaces_verdict(0.084, thesis_like).startswith("not met")  # no bend at 5 %
    turned_over = pooled.two_surfaces_verdict(0.01, pairs_at([24, 25, 23, 24], [8, 9, 7, 8]))
    assert turned_over == ("not met (toe mean − thesis +10.0 ± 0.4° (SE): no; "
                           "upper mean − thesis -16.0 ± 0.4° (SE): no)")  # the other way
    too_scattered = pooled.two_surfaces_verdict(0.01, pairs_at([0, 30, 10, 20], [10, 40, 20, 30]))
    assert too_scattered.startswith("undecided (toe")
    assert pooled.two_surfaces_verdict(0.01, thesis_like[:2]).startswith("undecided")
    assert pooled.two_surfaces_verdict(None, []).startswith("undecided")


def test_the_thesis_run_is_placed_among_the_draws_by_each_surface_and_both():
    pairs = pairs_at([10, 14, 20, 30], [30, 20, 24, 10])  # toe <= 14: 2; upper >= 24: 2; both: 1
    assert pooled.thesis_among_draws(pairs) == ("the thesis' run among these 4: toe φ ≤ 14° in 2, "
                                                "upper φ ≥ 24° in 2, both in 1")
