"""examples/field/galandrood.py end to end at a coarse resolution (a few hundred discs): the slope of
Fig 5-44 built, settled, jointed and judged; its summary, pictures and ParaView series."""
import glob
import os

from conftest import run_example

COARSE = dict(rmin=0.094, rmax=0.15, bond_gap=0.15, columns=20)  # 2 discs per layer: the test's cost, not the case


def test_the_example_runs_end_to_end_and_reports_beside_the_thesis(tmp_path):
    s = run_example("examples/field/galandrood.py", tmp_path, **COARSE)
    out = str(tmp_path / "out")
    assert s["failed"] in (True, False)
    assert s["thesis"]["dem_factor_of_safety"] == 1.62 and s["thesis"]["bftop_factor_of_safety"] == 1.3802
    if not s["failed"]:  # standing, it says how far its bonds are from breaking and tries the thesis' factor
        assert s["first_break_factor"] > 1 and s["reduced_trial"]["factor"] == 1.62
    assert os.path.exists(os.path.join(out, "monitoring_points.png"))
    assert glob.glob(os.path.join(out, "paraview", "discs_*.vtu"))
