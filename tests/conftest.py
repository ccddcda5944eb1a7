"""Fixtures for physics tests run in YADE's Python (``source scripts/env.sh`` first)."""
import importlib.util
import json
import os
import subprocess
import sys

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path[:0] = [os.path.join(REPO, "py"), REPO]  # toppling, and examples.params
os.environ["OMP_NUM_THREADS"] = "1"  # bitwise-reproducible runs (save/load test)

import yade  # noqa: E402,F401  (loads the plugin-enabled YADE, our classes included)
from yade import O  # noqa: E402

from examples.params import TABLE_5_6_ROCK as ROCK  # noqa: E402  (the block-on-a-joint tests' rock)


@pytest.fixture
def empty_scene():
    """A fresh, empty YADE scene."""
    O.reset()
    yield O
    O.reset()


def with_out(tmp_path, params: dict) -> dict:
    """``params`` with ``out`` defaulting to ``tmp_path/out``."""
    return {"out": str(tmp_path / "out"), **params}


def yade_command(path: str, tmp_path, threads: int = 1, **params) -> tuple[list[str], dict]:
    """The command and environment of ``./yade -x -n <path>`` run headless with ``params``
    (through a one-line readParamsFromTable table; see ``with_out``)."""
    params = with_out(tmp_path, params)
    table = tmp_path / "params.table"
    table.write_text(" ".join(params) + "\n" + " ".join(repr(v) if isinstance(v, str) else str(v)
                                                         for v in params.values()) + "\n")
    env = dict(os.environ, YADE_BATCH=f"{table}:2")
    return [os.path.join(REPO, "yade"), "-x", "-n", "-j", str(threads), os.path.join(REPO, path)], env


def run_yade(path: str, tmp_path, threads: int = 1, **params) -> subprocess.CompletedProcess:
    """Run ``yade_command``'s command to its end."""
    command, env = yade_command(path, tmp_path, threads, **params)
    return subprocess.run(command, env=env, capture_output=True, text=True, timeout=600)


def run_example(path: str, tmp_path, threads: int = 1, **params) -> dict:
    """Run an example as ``run_yade`` does and return its ``summary.json``."""
    params = with_out(tmp_path, params)
    proc = run_yade(path, tmp_path, threads, **params)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    with open(os.path.join(params["out"], "summary.json")) as f:
        return json.load(f)


def load_script(path: str):
    """The script at ``path`` (from the repository's root) as a module, to test its functions; its
    folder goes on the import path, as when it runs, for the siblings it imports."""
    folder = os.path.dirname(os.path.join(REPO, path))
    if folder not in sys.path:
        sys.path.insert(0, folder)
    name = os.path.splitext(os.path.basename(path))[0]
    spec = importlib.util.spec_from_file_location(name, os.path.join(REPO, path))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
