"""scripts/pooled_surfaces.py on made-up summaries: six runs on two surfaces that each alone
falls short of showing."""
import json
import math
import os
import re

import numpy as np
import pytest
from conftest import load_script

pooled = load_script("pooled_surfaces")


def write_runs(folder, n: int = 6) -> None:
    rng, x = np.random.default_rng(3), -np.arange(1, 11) * 0.05 + 0.025
    t1, t2, xb = math.tan(math.radians(14)), math.tan(math.radians(24)), -0.25
    y = np.where(x > xb, -t1 * x, -t1 * xb - t2 * (x - xb))
    for i in range(n):
        os.makedirs(folder / f"random_{i}")
        points = np.c_[x, y + rng.normal(0, 0.01, len(x))].tolist()
        (folder / f"random_{i}" / "summary.json").write_text(json.dumps({"failure_tilt_deg": 19.0, "failure_points": points}))
    os.makedirs(folder / "stood")
    (folder / "stood" / "summary.json").write_text(json.dumps({"failure_tilt_deg": None, "failure_points": []}))


def test_the_runs_of_a_pattern_are_pooled_and_the_cut_found(tmp_path, capsys):
    write_runs(tmp_path)
    pooled.main(str(tmp_path), ["random_*", "stood"])
    out = capsys.readouterr().out.splitlines()
    rows = [line for line in out if line.startswith("| random_")]
    assert len(rows) == 6
    at_cut = [[float(v) for v in row.split("|")[-2].split("/")] for row in rows]
    assert np.mean(at_cut, axis=0) == pytest.approx([14, 24], abs=3)  # each run's lines at the common cut
    assert out[-1].startswith("6 runs pooled: p = 0.00")
    cut_mm = float(re.search(r"common cut (\d+) mm from the toe", out[-1]).group(1))
    assert 150 < cut_mm < 350  # within a column of the break, 250 mm
    assert out[-1].endswith("the toe shallower in 6")
