"""README.md's Python example runs as printed (so that it cannot rot) and says what it measured."""
import os
import re
import subprocess

from conftest import REPO


def readme_example() -> str:
    with open(os.path.join(REPO, "README.md")) as f:
        return re.search(r"```python\n(.*?)```", f.read(), re.S).group(1)


def test_the_readme_example_builds_runs_and_reads_a_jointed_slope(tmp_path):
    script = tmp_path / "example.py"
    script.write_text(readme_example())
    proc = subprocess.run([os.path.join(REPO, "yade"), "-x", "-n", "-j1", str(script)], capture_output=True,
                          text=True, timeout=300, cwd=tmp_path)
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    moved, broken = re.search(r"crest moved ([\d.]+) mm, (\d+) bonds broken", proc.stdout).groups()
    # tilted 30 deg for 0.05 s the slope deforms under its weight and stands: the crest moves, by less than the
    # smallest disc's radius (a collapse, or bonds broken by locked-in overlap, would move it by centimetres)
    assert 0 < float(moved) < 3.0 and int(broken) >= 0
