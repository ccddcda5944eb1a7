"""A yade-batch table run on a Dask cluster: each selected line one task, finished lines skipped,
progress on the console while the tasks run."""
from __future__ import annotations

import logging
import math
import os
import time
import uuid
from dataclasses import dataclass
from typing import Any, Callable, Optional

from toppling.io.reader import summary_of
from toppling.run.sweep import batch_table, task

REPO = os.environ.get("TOPPLING_REPO") or os.path.abspath(os.path.join(os.path.dirname(__file__), *[os.pardir] * 4))


@dataclass
class Planned:
    """A selected line: where it writes, its log, the job a worker runs, and whether a summary of
    the same inputs is there already."""
    line: batch_table.Line
    out: str
    job: dict[str, Any]
    finished: bool


def plan(table_path: str, script: str, lines: Optional[str] = None, cwd: Optional[str] = None,
         yade: Optional[str] = None) -> list[Planned]:
    """The jobs for ``lines`` of the table (all if None), run from ``cwd`` (relative outs are
    relative to it, as under yade-batch)."""
    cwd = os.path.abspath(cwd or os.getcwd())
    table_path, script = (os.path.abspath(os.path.join(cwd, p)) for p in (table_path, script))
    for name, path in (("TABLE", table_path), ("SCRIPT", script)):
        if not os.path.isfile(path):
            raise ValueError(f"{name} {path} does not exist")
    table = batch_table.read(table_path)
    selected = table.select(lines)
    script_of = lambda line: os.path.join(cwd, line.directives().get("SCRIPT", script))  # noqa: E731
    outs = batch_table.outs(selected, script_of)
    yade = yade or os.path.join(REPO, "yade")
    planned = []
    for line in selected:
        out = os.path.join(cwd, outs[line.number])
        directives = line.directives()
        threads = int(directives.pop("THREADS", directives.pop("OMP_NUM_THREADS", 1)))
        directives.pop("SCRIPT", None)
        job = {"table": table_path, "line": line.number, "cwd": cwd, "log": out + ".log", "env": directives,
               "command": [yade, "-x", "-n", f"-j{threads}", script_of(line)]}
        planned.append(Planned(line, out, job, finished(line, out)))
    return planned


def finished(line: batch_table.Line, out: str) -> bool:
    """A summary.json in ``out`` written by a run of the same inputs."""
    return batch_table.same_inputs(line, summary_of(out))


def skipped(planned: list[Planned]) -> dict[int, dict[str, Any]]:
    """The results of the lines a sweep need not run."""
    return {p.line.number: {"line": p.line.number, "status": "skipped"} for p in planned if p.finished}


def connect(scheduler: Optional[str], workers: int):
    """A client of the scheduler at ``scheduler`` (an address, or the file ``dask-scheduler
    --scheduler-file`` wrote; Dask's TLS settings from its configuration), or
    of a local cluster of ``workers`` one-thread worker processes listening on 127.0.0.1 only (their
    HTTP endpoints too). Returns (client, local cluster or None)."""
    from distributed import Client, LocalCluster
    if scheduler and os.path.isfile(scheduler):
        return Client(scheduler_file=scheduler, timeout="30s"), None
    if scheduler:
        return Client(scheduler, timeout="30s"), None
    # with or without a dashboard, the scheduler and each worker serve HTTP (health, metrics), on
    # every interface unless told where
    loopback = "127.0.0.1:0"
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                           dashboard_address=loopback, worker_dashboard_address=loopback, silence_logs=logging.ERROR)
    return Client(cluster), cluster


def execute(planned: list[Planned], client, echo: Callable[[str], None] = print,
            every: float = 60.0) -> dict[int, dict[str, Any]]:
    """Run the unfinished lines on the client's cluster; a result per line number (finished lines:
    status "skipped"). A worker that dies has its task run again elsewhere (Dask's rule: up to
    ``distributed.scheduler.allowed-failures`` deaths per task); a run that fails by itself is
    reported, not retried."""
    import cloudpickle
    from distributed import wait
    cloudpickle.register_pickle_by_value(task)
    results = skipped(planned)
    tag = uuid.uuid4().hex[:8]
    futures = {client.submit(task.run_job, p.job, key=f"toppling-sweep-{tag}-line-{p.line.number}", pure=False): p
               for p in planned if not p.finished}
    progress = Progress(len(planned), len(results), echo)
    progress.show(client, futures, force=True)
    pending = set(futures)
    while pending:
        try:
            done, pending = wait(pending, timeout=2.0, return_when="FIRST_COMPLETED")
        except TimeoutError:  # none finished within the timeout
            done = set()
        for future in done:
            p = futures[future]
            try:
                result = future.result()
            except Exception as e:  # the task's worker died too often (KilledWorker) or the task raised
                result = {"line": p.line.number, "status": "failed", "last_log_line": f"{type(e).__name__}: {e}"}
            results[p.line.number] = result
            progress.finished(p, result)
        progress.show(client, pending, force=bool(done), every=every)
    return results


class Progress:
    """Console lines: done / running / failed / skipped, and an ETA from the finished runs' wall times."""

    def __init__(self, total: int, skipped: int, echo: Callable[[str], None]):
        self.total, self.skipped, self.echo = total, skipped, echo
        self.walls: list[float] = []
        self.failed = 0
        self.workers = 1
        self.last = 0.0

    def finished(self, p: Planned, result: dict[str, Any]) -> None:
        if result["status"] == "failed":
            self.failed += 1
        elif "wall_time" in result:
            self.walls.append(result["wall_time"])
        wall = f" in {result['wall_time']:.1f} s on {result['host']}" if "wall_time" in result else ""
        self.echo(f"sweep: line {p.line.number} ({p.line.description}) {result['status']}{wall}")

    def show(self, client, pending, force: bool = False, every: float = 60.0) -> None:
        if not force and time.monotonic() - self.last < every:
            return
        self.last = time.monotonic()
        keys = {f.key for f in pending}
        self.workers = max(1, sum(client.nthreads().values()))
        # a worker holds more tasks than it runs at once: the rest wait there
        running = min(self.workers, sum(len(keys.intersection(k)) for k in client.processing().values()))
        done = self.total - self.skipped - self.failed - len(keys)
        self.echo(f"sweep: {done} done, {running} running, {len(keys) - running} queued, {self.failed} failed, "
                  f"{self.skipped} skipped of {self.total}; ETA {self.eta(len(keys))}")

    def eta(self, left: int) -> str:
        if not left:
            return "0 s"
        if not self.walls:
            return "after the first run"
        seconds = sum(self.walls) / len(self.walls) * math.ceil(left / self.workers)
        return f"{seconds / 60:.0f} min" if seconds >= 120 else f"{seconds:.0f} s"
