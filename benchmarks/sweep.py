"""The engine's overhead: the same table lines run by ``yade-batch -j2 --job-threads 1`` and by
``toppling-sweep`` on a 2-worker local cluster (its start included), alternately, each from an
empty folder; prints both wall times per repeat, their medians and the overhead per task, and
whether the two wrote the same summaries. Plain Python, the machine otherwise idle:

    python3 benchmarks/sweep.py [TABLE SCRIPT LINES REPEATS]
    (default: examples/verification/tilt_slide.table examples/verification/tilt_slide.py 2-9 3)
"""
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(REPO, "py"))
from toppling.run.sweep import batch_table  # noqa: E402


def timed(command: list[str], cwd: str) -> float:
    start = time.monotonic()
    subprocess.run(command, cwd=cwd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.monotonic() - start


def summaries(folder: str) -> dict[str, dict]:
    found = {}
    for root, _, files in os.walk(folder):
        if "summary.json" in files:
            with open(os.path.join(root, "summary.json")) as f:
                found[os.path.relpath(root, folder)] = json.load(f)
    return found


def main(table: str, script: str, lines: str, repeats: int) -> None:
    table, script = os.path.abspath(table), os.path.abspath(script)
    count = len(batch_table.read(table).select(lines))
    commands = {"yade-batch": [os.path.join(REPO, "yade-batch"), "-j2", "--job-threads", "1", "--lines", lines,
                               "--log", "@.log", table, script],
                "toppling-sweep": [os.path.join(REPO, "toppling-sweep"), table, script, "--lines", lines, "--workers", "2"]}
    walls = {name: [] for name in commands}
    with tempfile.TemporaryDirectory() as scratch:
        for repeat in range(repeats):
            for name, command in commands.items():
                folder = os.path.join(scratch, name)
                shutil.rmtree(folder, ignore_errors=True)
                os.makedirs(folder)
                walls[name].append(timed(command, folder))
                print(f"repeat {repeat + 1}: {name} {walls[name][-1]:.2f} s", flush=True)
        same = summaries(os.path.join(scratch, "yade-batch")) == summaries(os.path.join(scratch, "toppling-sweep"))
    median = {name: statistics.median(w) for name, w in walls.items()}
    overhead = (median["toppling-sweep"] - median["yade-batch"]) / count
    print(json.dumps({"lines": count, "median_wall_s": median, "overhead_per_task_s": round(overhead, 3),
                      "same_summaries": same}))


if __name__ == "__main__":
    args = sys.argv[1:] or ["examples/verification/tilt_slide.table", "examples/verification/tilt_slide.py", "2-9", "3"]
    main(args[0], args[1], args[2], int(args[3]))
