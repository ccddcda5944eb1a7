"""A checkpoint is one unit: the scene and the driver's state inside it come from one moment,
however the run that saved it was stopped."""
import bz2
import json
import os
import random
import signal
import subprocess
import time

import pytest
from conftest import REPO
from lattice import R, material
from yade import O

from toppling.build import engines
from toppling.build.discs import disc
from toppling.run.checkpoint import Checkpoint
from toppling.run.steps import run_steps


def falling_disc() -> None:
    O.bodies.append(disc((0, 1), R, material()))
    O.engines = engines.engines(timestepper=False)
    O.dt = 1e-4


def test_a_run_killed_between_the_scene_and_its_copy_resumes_from_one_moment(empty_scene, tmp_path, monkeypatch):
    falling_disc()
    checkpoint = Checkpoint(str(tmp_path))
    run_steps(10)
    checkpoint.save({"iter": O.iter})
    run_steps(10)
    renames = []

    def dies_at_the_second_rename(src, dst):
        renames.append(dst)
        if len(renames) == 2:
            raise KeyboardInterrupt("killed")
        os.rename(src, dst)

    monkeypatch.setattr("toppling.run.checkpoint.os.replace", dies_at_the_second_rename)
    with pytest.raises(KeyboardInterrupt):
        checkpoint.save({"iter": O.iter})
    monkeypatch.undo()
    state = checkpoint.load()
    assert state["iter"] == O.iter == 20  # the scene's own moment, whatever the copy says
    assert json.loads((tmp_path / "checkpoint.json").read_text())["iter"] == 10


SAVER = """
import sys
from toppling.build import engines
from toppling.build.discs import disc
from toppling.run.checkpoint import Checkpoint
from toppling.run.steps import run_steps
from lattice import R, material
from yade import O
checkpoint = Checkpoint(sys.argv[1])
if checkpoint.exists():
    checkpoint.load()
else:
    O.bodies.append(disc((0, 1), R, material()))
    O.engines = engines.engines(timestepper=False)
    O.dt = 1e-4
print("SAVING", flush=True)
while True:
    run_steps(1)
    checkpoint.save({"iter": O.iter, "y": O.bodies[0].state.pos[1]})
"""


def test_a_run_killed_at_random_moments_always_leaves_a_whole_checkpoint(tmp_path):
    script = tmp_path / "saver.py"
    script.write_text(SAVER)
    env = dict(os.environ, PYTHONPATH=os.path.join(REPO, "tests", "python") + os.pathsep + os.environ["PYTHONPATH"])
    folder = tmp_path / "run"
    rng = random.Random(7)
    for _ in range(5):
        proc = subprocess.Popen([os.path.join(REPO, "yade"), "-x", "-n", "-j1", str(script), str(folder)],
                                env=env, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        assert any(line.startswith("SAVING") for line in proc.stdout)  # after YADE's greeting
        time.sleep(rng.uniform(0.2, 1.0))  # a save takes milliseconds: most kills land in one
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        O.reset()
        state = Checkpoint(str(folder)).load()
        assert state["iter"] == O.iter and state["y"] == O.bodies[0].state.pos[1]
    O.reset()


def test_a_checkpoint_that_cannot_be_loaded_is_refused_by_name(empty_scene, tmp_path):
    """A scene file YADE cannot read (another build's classes, a damaged file) stops with the file and the way on."""
    checkpoint = Checkpoint(str(tmp_path))
    (tmp_path / "checkpoint.json").write_text("{}")
    (tmp_path / "checkpoint.yade.bz2").write_bytes(bz2.compress(b"<not a YADE scene>"))
    with pytest.raises(ValueError, match="checkpoint.yade.bz2 cannot be loaded .*resume=0 starts afresh"):
        checkpoint.load()
