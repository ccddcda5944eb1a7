"""toppling.io.reader: a run folder read back (summary, pictures, ParaView series), and many runs' summaries."""
import json

import pytest

from toppling.io.reader import read_run, read_summaries, summary_of


def test_a_run_folder_reads_back_its_summary_pictures_and_series(tmp_path):
    (tmp_path / "paraview").mkdir()
    for name in ("summary.json", "slope_before.png", "slope_after.png", "paraview/discs.pvd", "paraview/cracks.pvd"):
        (tmp_path / name).write_text(json.dumps({"failed": True, "failure_tilt_deg": 38.0}))
    run = read_run(str(tmp_path))
    assert run["summary"]["failure_tilt_deg"] == 38.0
    assert [p.rsplit("/", 1)[1] for p in run["pictures"]] == ["slope_after.png", "slope_before.png"]
    assert sorted(run["paraview"]) == ["cracks", "discs"]


def test_a_run_without_a_summary_says_it_has_not_finished(tmp_path):
    with pytest.raises(FileNotFoundError, match="has not finished"):
        read_run(str(tmp_path))


def test_summaries_are_read_by_run_name_where_the_name_matches(tmp_path):
    for name in ("ideal_seed1", "ideal_seed2", "random"):
        (tmp_path / name).mkdir()
        (tmp_path / name / "summary.json").write_text(json.dumps({"name": name}))
    assert sorted(read_summaries(str(tmp_path), ["ideal_*"])) == ["ideal_seed1", "ideal_seed2"]
    assert len(read_summaries(str(tmp_path))) == 3


def test_summary_of_is_empty_until_a_readable_summary_is_there(tmp_path):
    assert summary_of(str(tmp_path / "missing")) == {}
    (tmp_path / "summary.json").write_text('{"inputs": {"a": 1}, "fai')  # a run killed while writing it
    assert summary_of(str(tmp_path)) == {}
    (tmp_path / "summary.json").write_text(json.dumps({"inputs": {"a": 1}, "failed": False}))
    assert summary_of(str(tmp_path)) == {"inputs": {"a": 1}, "failed": False}


def test_results_added_to_a_summary_keep_its_inputs_and_figures(tmp_path):
    from toppling.io import output
    output.write_summary(str(tmp_path), {"a": 1}, failed=False)
    output.add_to_summary(str(tmp_path), first_break_factor=12.5)
    assert summary_of(str(tmp_path)) == {"inputs": {"a": 1}, "failed": False, "first_break_factor": 12.5,
                                         "code": output.CODE}
