"""toppling.io.output: what every run writes beside its results."""
import os
import subprocess

from toppling.io import output
from toppling.io.reader import summary_of


def test_a_summary_names_the_commit_of_the_code_that_ran():
    head = subprocess.run(["git", "rev-parse", "HEAD"], cwd=os.path.dirname(output.__file__), capture_output=True,
                          text=True).stdout.strip()
    code = output.code_version()
    assert code["commit"] == head and len(head) == 40
    assert isinstance(code["modified"], bool)


def test_outside_a_checkout_the_code_is_none_and_the_summary_still_written(tmp_path, monkeypatch):
    def no_git(*args):
        raise FileNotFoundError("git")
    monkeypatch.setattr(output, "_git", no_git)
    assert output.code_version() is None
    monkeypatch.setattr(output, "CODE", None)
    output.write_summary(str(tmp_path), {"a": 1}, failed=True)
    assert summary_of(str(tmp_path)) == {"inputs": {"a": 1}, "failed": True, "code": None}
