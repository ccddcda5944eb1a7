"""toppling-sweep: a table's lines as Dask tasks, on a local cluster or on a scheduler and workers
started apart (as on a cluster); the same summaries as yade-batch; a dead worker's task run
elsewhere; a failing line reported; a finished sweep not run again; nothing listening beyond
127.0.0.1."""
import json
import os
import signal
import subprocess
import time

import pytest
from conftest import REPO

from toppling.run.sweep import sweep

SWEEP = os.path.join(REPO, "toppling-sweep")
FREE_FALL = os.path.join(REPO, "examples", "verification", "free_fall.py")
FOUR_DROPS = "description drop steps out\nd1 1.0 3000 'out/d1'\nd2 0.5 3000 'out/d2'\nd3 0.8 3000 'out/d3'\nd4 1.2 3000 'out/d4'\n"
# a job that says it started (its pid) and waits: long enough to kill its worker under it
JOB = """import json, os, time
from yade.utils import readParamsFromTable
readParamsFromTable(seconds=0.0, value=1.0, out='out', noTableOk=True)
from yade.params import table
from toppling.io import output
if table.value < 0:
    raise ValueError(f"value = {table.value}: give 0 or more")
os.makedirs(table.out, exist_ok=True)
open(os.path.join(table.out, 'started'), 'w').write(str(os.getpid()))
time.sleep(table.seconds)
output.write_summary(table.out, output.table_inputs(table), double=2 * table.value)
"""


def run_sweep(cwd, *args, timeout=300):
    return subprocess.run([SWEEP, *map(str, args)], cwd=cwd, capture_output=True, text=True, timeout=timeout)


def summaries(folder):
    return {name: json.load(open(os.path.join(folder, name, "summary.json"))) for name in sorted(os.listdir(folder))
            if os.path.isdir(os.path.join(folder, name))}


def gone(pid, within=10.0):
    """Whether process ``pid`` ends within ``within`` seconds."""
    for _ in range(int(within / 0.1)):
        if not os.path.exists(f"/proc/{pid}"):
            return True
        time.sleep(0.1)
    return False


def test_a_local_cluster_writes_the_summaries_yade_batch_writes_and_a_second_sweep_does_no_work(tmp_path):
    (tmp_path / "drops.table").write_text(FOUR_DROPS)
    for where in ("batch", "sweep"):
        (tmp_path / where).mkdir()
    batch = subprocess.run([os.path.join(REPO, "yade-batch"), "-j2", "--job-threads", "1", "--log", "@.log",
                            str(tmp_path / "drops.table"), FREE_FALL], cwd=tmp_path / "batch", capture_output=True,
                           text=True, timeout=300)
    assert batch.returncode == 0, batch.stdout[-2000:]
    first = run_sweep(tmp_path / "sweep", tmp_path / "drops.table", FREE_FALL, "--workers", 2)
    assert first.returncode == 0, first.stdout[-2000:] + first.stderr[-2000:]
    assert first.stdout.count(" done in ") == 4
    assert summaries(tmp_path / "sweep" / "out") == summaries(tmp_path / "batch" / "out")
    logs = {p: p.stat().st_mtime_ns for p in (tmp_path / "sweep" / "out").glob("*.log")}
    assert len(logs) == 4  # each beside its out
    again = run_sweep(tmp_path / "sweep", tmp_path / "drops.table", FREE_FALL, "--figures", "measured")
    assert again.returncode == 0 and "4 finished already" in again.stdout and again.stdout.count("| skipped |") == 4
    assert {p: p.stat().st_mtime_ns for p in logs} == logs


def listening_addresses(pids):
    """Local addresses (hex, as /proc/net/tcp* gives them) of the sockets these processes listen on."""
    inodes = set()
    for pid in pids:
        for fd in os.listdir(f"/proc/{pid}/fd"):
            try:
                target = os.readlink(f"/proc/{pid}/fd/{fd}")
            except OSError:
                continue
            if target.startswith("socket:"):
                inodes.add(int(target[8:-1]))
    found = []
    for table in ("/proc/net/tcp", "/proc/net/tcp6"):
        for row in open(table).read().splitlines()[1:]:
            field = row.split()
            if field[3] == "0A" and int(field[9]) in inodes:
                found.append(field[1].split(":")[0])
    return found


def descendants(pid):
    children = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                children.setdefault(int(open(f"/proc/{entry}/stat").read().rsplit(")", 1)[1].split()[1]), []).append(int(entry))
            except OSError:
                continue
    found, todo = [], [pid]
    while todo:
        found.append(todo.pop())
        todo += children.get(found[-1], [])
    return found


def test_the_local_cluster_listens_on_the_loopback_interface_only():
    client, cluster = sweep.connect(None, 2)
    try:
        client.wait_for_workers(2)
        addresses = listening_addresses(descendants(os.getpid()))
    finally:
        client.close()
        cluster.close()
    assert len(addresses) >= 3  # the scheduler and each worker (and its nanny)
    assert set(addresses) == {"0100007F"}  # 127.0.0.1


@pytest.fixture
def cluster(tmp_path):
    """A scheduler and two one-thread workers started apart on 127.0.0.1, as a user starts them on a cluster."""
    info = tmp_path / "scheduler.json"
    loopback = ["--host", "127.0.0.1", "--dashboard-address", "127.0.0.1:0"]
    processes = [subprocess.Popen(["dask-scheduler", "--port", "0", "--scheduler-file", str(info), *loopback],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)]
    for _ in range(60):
        if info.exists() and info.stat().st_size:
            break
        time.sleep(0.5)
    address = json.loads(info.read_text())["address"]
    bare = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "TOPPLING_REPO")}  # no toppling needed
    workers = [subprocess.Popen(["dask-worker", address, "--nthreads", "1", "--no-nanny", *loopback], env=bare,
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL) for _ in range(2)]
    yield address, workers, str(info)
    for p in workers + processes:
        p.kill()
        p.wait()


def test_a_scheduler_started_apart_runs_the_table_through_its_address_or_its_file(tmp_path, cluster):
    address, _, info = cluster
    (tmp_path / "drops.table").write_text(FOUR_DROPS)
    done = run_sweep(tmp_path, tmp_path / "drops.table", FREE_FALL, "--scheduler", address, "--lines", "2-3")
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    done = run_sweep(tmp_path, tmp_path / "drops.table", FREE_FALL, "--scheduler", info)
    assert done.returncode == 0 and "2 finished already" in done.stdout, done.stdout[-2000:] + done.stderr[-2000:]
    assert sorted(summaries(tmp_path / "out")) == ["d1", "d2", "d3", "d4"]


def test_a_killed_worker_has_its_line_run_elsewhere_and_a_failing_line_is_reported(tmp_path, cluster):
    address, workers, _ = cluster
    (tmp_path / "job.py").write_text(JOB)
    (tmp_path / "jobs.table").write_text("description seconds value out\nkilled 6.0 1.0 'out/killed'\n"
                                         "other 6.0 2.0 'out/other'\nbad 0.0 -1.0 'out/bad'\n")
    sweeping = subprocess.Popen([SWEEP, str(tmp_path / "jobs.table"), str(tmp_path / "job.py"), "--scheduler", address],
                                cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    started = tmp_path / "out" / "killed" / "started"
    for _ in range(120):
        if started.exists() and started.read_text():
            break
        time.sleep(0.25)
    run = int(started.read_text())
    worker = int(open(f"/proc/{run}/stat").read().rsplit(")", 1)[1].split()[1])  # the yade run's parent
    assert worker in [w.pid for w in workers]
    os.kill(worker, signal.SIGKILL)
    output, _ = sweeping.communicate(timeout=300)
    assert gone(run)  # the run died with its worker
    assert sweeping.returncode == 1, output  # the bad line failed
    assert "| killed | done |" in output and "| other | done |" in output and "| bad | failed |" in output
    assert "line 4 (bad): ValueError: value = -1.0: give 0 or more" in output
    assert json.load(open(tmp_path / "out" / "killed" / "summary.json"))["double"] == 2.0
    assert (tmp_path / "out" / "killed.log").read_text().count("# toppling-sweep: line 2") == 2  # run twice


def test_a_stopped_sweep_stops_its_runs_and_the_same_command_finishes_it(tmp_path):
    (tmp_path / "job.py").write_text(JOB)
    (tmp_path / "jobs.table").write_text("description seconds out\nquick 0.0 'out/quick'\nslow 60.0 'out/slow'\n")
    command = [SWEEP, str(tmp_path / "jobs.table"), str(tmp_path / "job.py"), "--workers", "2"]
    sweeping = subprocess.Popen(command, cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    slow = tmp_path / "out" / "slow" / "started"
    for _ in range(120):
        if (tmp_path / "out" / "quick" / "summary.json").exists() and slow.exists() and slow.read_text():
            break
        time.sleep(0.25)
    sweeping.send_signal(signal.SIGTERM)  # as a batch system ends a job
    output, _ = sweeping.communicate(timeout=60)
    assert sweeping.returncode == 130 and "run the same command again" in output, output
    assert gone(int(slow.read_text()))
    (tmp_path / "jobs.table").write_text("description seconds out\nquick 0.0 'out/quick'\nslow 0.0 'out/slow'\n")
    # (the slow line made quick: its inputs changed, so it runs; the quick one is kept)
    again = subprocess.run(command, cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert again.returncode == 0 and "1 finished already" in again.stdout, again.stdout + again.stderr
    assert "| quick | skipped |" in again.stdout and "| slow | done |" in again.stdout
