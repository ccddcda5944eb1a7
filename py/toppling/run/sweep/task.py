"""One line of a sweep, run on a Dask worker: ``./yade -x -n -jN SCRIPT`` with ``YADE_BATCH=table:line``,
as yade-batch runs it. Standard library only: the client sends this module to the workers by value,
so a worker needs Dask, the shared checkout and the shared results folder, not our package."""
from __future__ import annotations

import os
import socket
import subprocess
import time
from typing import Any

# the run dies with the worker: a task that Dask re-runs elsewhere never races a stray copy of itself
DIE_WITH_WORKER = ["setpriv", "--pdeathsig", "SIGKILL", "--"]


def run_job(job: dict[str, Any]) -> dict[str, Any]:
    """Run one line; never raises for a failed run (a bad parameter is not retried): returns its
    status (done, failed), exit code, wall time, worker host and the last line of its log."""
    env = dict(os.environ, YADE_BATCH=f"{job['table']}:{job['line']}", DISPLAY="", **job["env"])
    os.makedirs(os.path.dirname(job["log"]) or ".", exist_ok=True)
    host = socket.gethostname()
    start = time.monotonic()
    with open(job["log"], "a") as log:
        log.write(f"# toppling-sweep: line {job['line']} of {job['table']} on {host}, {time.asctime()}\n")
        log.flush()
        begin = log.tell()
        code = subprocess.run(DIE_WITH_WORKER + job["command"], cwd=job["cwd"], env=env, stdout=log,
                              stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL).returncode
    tail = log_tail(job["log"], begin)
    last = tail[-1] if tail else ""
    # yade-batch's rule: a run that printed YADE's normal exit is done whatever its exit code
    done = code == 0 or any(s.startswith("Yade: normal exit.") for s in tail)
    return {"line": job["line"], "status": "done" if done else "failed", "exit_code": code,
            "wall_time": time.monotonic() - start, "host": host, "last_log_line": last}


def log_tail(path: str, begin: int) -> list[str]:
    """The non-empty lines of the last 4 kB this run wrote to its log (from offset ``begin``)."""
    with open(path, "rb") as f:
        f.seek(max(begin, os.path.getsize(path) - 4096))
        return [s.strip() for s in f.read().decode(errors="replace").splitlines() if s.strip()]
