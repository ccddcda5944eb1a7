"""toppling.run.sweep.batch_table reads every table as YADE reads it, finds each line's out folder,
and knows a summary written by the same inputs."""
import glob
import os

import pytest
from conftest import REPO

from toppling.run.sweep import batch_table
from yade.utils import TableParamReader

TABLES = sorted(path for folder in ("examples", "calibration", "benchmarks")
                for path in glob.glob(os.path.join(REPO, folder, "**", "*.table"), recursive=True))
ODD = """# a comment line
x y! z
1 2 3   # comment after values

4 = 'a'
= 2 *
"""


@pytest.mark.parametrize("path", TABLES, ids=lambda p: os.path.relpath(p, REPO))
def test_every_committed_table_reads_as_yade_reads_it_and_its_values_evaluate(path):
    ours = batch_table.read(path)
    yade = TableParamReader(path).paramDict()
    assert list(ours.lines) == sorted(yade)
    for number, line in ours.lines.items():
        assert {**line.values, "description": line.description} == yade[number]
        line.parameters()  # a word without quotes would stop the job at its start (NameError)


def test_repeats_bangs_comments_and_repeated_descriptions_read_as_yade_reads_them(tmp_path):
    path = tmp_path / "odd.table"
    path.write_text(ODD)
    ours = batch_table.read(str(path))
    yade = TableParamReader(str(path)).paramDict()
    assert {n: {**l.values, "description": l.description} for n, l in ours.lines.items()} == yade
    assert [l.description for l in ours.lines.values()] == ["y=2", "y=2__line=5__", "y=2__line=6__"]
    assert ours.lines[6].parameters() == {"x": 4, "y": 2}  # '*': the script's default, not sent


def test_lines_are_selected_in_yade_batch_form_and_unknown_lines_are_refused(tmp_path):
    path = tmp_path / "odd.table"
    path.write_text(ODD)
    table = batch_table.read(str(path))
    assert [l.number for l in table.select("3,5-6")] == [3, 5, 6]
    with pytest.raises(ValueError, match="no parameter set on line.*4"):
        table.select("3-4")
    with pytest.raises(ValueError, match="neither a line number nor a range"):
        table.select("3,x")


def test_out_comes_from_the_table_else_from_the_script_and_two_lines_may_not_share_it(tmp_path):
    script = tmp_path / "job.py"
    script.write_text("from yade.utils import readParamsFromTable\nreadParamsFromTable(a=1, out='results/job')\n")
    with_out = tmp_path / "with_out.table"
    with_out.write_text("a out\n1 'r/one'\n2 'r/two/'\n")
    lines = batch_table.read(str(with_out)).select(None)
    assert batch_table.outs(lines, lambda line: str(script)) == {2: "r/one", 3: "r/two"}
    without = tmp_path / "without.table"
    without.write_text("a\n1\n2\n")
    lines = batch_table.read(str(without)).select(None)
    assert batch_table.outs(lines[:1], lambda line: str(script)) == {2: "results/job"}
    with pytest.raises(ValueError, match="lines 2 and 3 both write to out = 'results/job'"):
        batch_table.outs(lines, lambda line: str(script))


def test_a_summary_counts_as_this_lines_only_if_it_holds_the_same_inputs(tmp_path):
    path = tmp_path / "t.table"
    path.write_text("phi rmax shape out\n30.0 0.004 (1,2) 'o'\n")
    line = batch_table.read(str(path)).lines[2]
    inputs = {"phi": 30.0, "rmax": 0.004, "shape": [1, 2], "out": "o", "seed": 1}
    assert batch_table.same_inputs(line, {"inputs": inputs})
    assert not batch_table.same_inputs(line, {"inputs": {**inputs, "phi": 31.0}})
    assert not batch_table.same_inputs(line, {"inputs": {k: v for k, v in inputs.items() if k != "rmax"}})
    assert not batch_table.same_inputs(line, {"failed": True})
