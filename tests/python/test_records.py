"""toppling.io.records: a study's record of finished runs, kept across machines."""
import json

from toppling.io import records

NUMBERS = ("seed", "phi_overall_deg", "wall_time")


def summary(seed: int, phi=None) -> dict:
    return {"inputs": {"seed": seed}, "phi_overall_deg": phi, "wall_time": 400.5,
            "code": {"commit": "0123456", "modified": True}}


def row(name: str, s: dict) -> dict:
    return {"run": name, "seed": s["inputs"]["seed"], "phi_overall_deg": s["phi_overall_deg"],
            "wall_time": s["wall_time"], "commit": records.commit(s)}


def write_runs(folder, runs: dict) -> None:
    for name, s in runs.items():
        (folder / name).mkdir(parents=True)
        (folder / name / "summary.json").write_text(json.dumps(s))


def test_runs_are_added_to_the_record_read_back_as_numbers_and_a_rerun_replaces_its_row(tmp_path):
    path = str(tmp_path / "runs.csv")
    write_runs(tmp_path / "a", {"base_s1": summary(1, 14.5), "t57_I_17-16_s1": summary(1)})
    records.update(path, str(tmp_path / "a"), row, NUMBERS)
    write_runs(tmp_path / "b", {"base_s1": summary(1, 16.0), "base_s2": summary(2, 12.0)})  # another machine
    rows = records.update(path, str(tmp_path / "b"), row, NUMBERS)
    assert rows == records.read(path, NUMBERS)
    assert sorted(rows) == ["base_s1", "base_s2", "t57_I_17-16_s1"]
    assert rows["base_s1"]["phi_overall_deg"] == 16.0
    first = rows["t57_I_17-16_s1"]
    assert (first["seed"], first["phi_overall_deg"], first["wall_time"]) == (1.0, None, 400.5)
    assert first["commit"] == "0123456+modified"  # text, though it reads as a number


def test_a_studys_first_record_makes_its_folder(tmp_path):
    path = str(tmp_path / "records" / "runs.csv")
    write_runs(tmp_path / "a", {"base_s1": summary(1, 14.5)})
    assert list(records.update(path, str(tmp_path / "a"), row, NUMBERS)) == ["base_s1"]


def test_a_figure_added_to_a_study_later_reads_as_none_in_the_older_rows(tmp_path):
    path = str(tmp_path / "runs.csv")
    write_runs(tmp_path / "a", {"base_s1": summary(1, 14.5)})
    records.update(path, str(tmp_path / "a"), row, NUMBERS)
    write_runs(tmp_path / "b", {"base_s2": {**summary(2, 12.0), "rmax": 0.1}})
    rows = records.update(path, str(tmp_path / "b"), lambda n, s: {**row(n, s), "rmax": s["rmax"]}, (*NUMBERS, "rmax"))
    assert (rows["base_s1"]["rmax"], rows["base_s2"]["rmax"]) == (None, 0.1)


def test_no_record_yet_has_no_rows(tmp_path):
    assert records.read(str(tmp_path / "none.csv"), NUMBERS) == {}


def test_missing_names_the_table_lines_whose_run_the_record_lacks(tmp_path):
    table = tmp_path / "t.table"
    table.write_text("description seed out\nbase_s1 1 'r/base_s1'\nbase_s2 2 'r/base_s2'\nx_s1 1 'r/x_s1/'\n")
    assert records.missing(str(table), {"base_s2": {}}) == "2,4"
