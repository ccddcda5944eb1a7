"""calibration/equivalent_slope/families_report.py: what the families' runs cost, by family."""
from conftest import load_script

report = load_script("calibration/equivalent_slope/families_report.py")


def test_cost_groups_runs_by_the_thesis_table_of_their_case_with_the_base_model_apart(capsys):
    cases = {"base": {"table": "5-7"}, "t57_I": {"table": "5-7"}, "t57_II": {"table": "5-7"},
             "t58_I": {"table": "5-8"}, "t59_I": {"table": "5-9"}}
    run = lambda wall, steps: {"wall_time": wall, "steps": steps}  # noqa: E731
    ours = {"base": [run(400.0, 80_000)], "t57_I": [run(900.0, 70_000), run(1100.0, 72_000)],
            "t57_II": [run(1000.0, 71_000)], "t58_I": [run(500.0, 60_000)]}
    report.cost(cases, ours)
    rows = capsys.readouterr().out.splitlines()[2:]
    assert rows == ["| base model | 1 | 400 | 400–400 | 80,000 |",
                    "| Table 5-7 | 3 | 1000 | 900–1100 | 71,000 |",
                    "| Table 5-8 | 1 | 500 | 500–500 | 60,000 |"]  # Table 5-9 not run: no row
