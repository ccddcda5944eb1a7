"""The tilting-table example stops on bad parameters with a message naming them, before it builds anything."""
import json
import os
import random
import signal
import subprocess
import time

import pytest
from conftest import run_example, run_yade, yade_command

EXAMPLE = "examples/tilting_table/run.py"


@pytest.mark.parametrize("name, value, valid", [("timestep_safety", 0.0, "in (0, 1]"), ("timestep_safety", 1.5, "in (0, 1]"),
                                               ("joint_stiffness_scale", 0.0, "in (0, 1]"),
                                               ("joint_stiffness_scale", 2.0, "in (0, 1]"),
                                               ("bond_gap", 0.01, "in (0, rmax] m"),
                                               ("damping", 1.0, "in [0, 1)"), ("settle_damping", -0.1, "in [0, 1)"),
                                               ("stage_rate", -1.0, "in [0, inf)"), ("start_tilt", -1.0, "in [0, 90)"),
                                               ("max_tilt", 90.0, "in [26.0, 90)"), ("max_wall_time", -1.0, "in [0, inf)"),
                                               ("layout_seed", 1.5, "an integer >= 0"),
                                               ("cut_rules", 2, "0 or 1"), ("joint_pieces", 2, "0 or 1"),
                                               ("z_order", 2, "0 or 1"),
                                               ("bond_tensile_strength", 300e3, "0 (the thesis' table) or in its "
                                                                                "range [13500, 209000]"),
                                               ("arrest_time", -1.0, "in [0, inf)"),
                                               ("arrangement", "slanted", "'ideal' or 'random'")])
def test_a_parameter_out_of_range_stops_the_run(tmp_path, name, value, valid):
    proc = run_yade(EXAMPLE, tmp_path, rmin=0.002, rmax=0.008, **{name: value})
    assert proc.returncode != 0
    shown = repr(value) if isinstance(value, str) else value
    assert f"{name} = {shown} is invalid: it must be {valid}" in proc.stderr + proc.stdout
    assert not (tmp_path / "out").exists()


def mounted_tmpfs(path, options: str):
    """A tmpfs at ``path`` (root only), unmounted by the caller."""
    if os.geteuid() != 0:
        pytest.skip("needs root to mount a tmpfs")
    path.mkdir()
    subprocess.run(["mount", "-t", "tmpfs", "-o", options, "tmpfs", str(path)], check=True)
    return path


@pytest.mark.parametrize("options, says", [("size=1m", "MB free and the run needs about"),
                                           ("size=64m,ro", "cannot be written (Read-only file system)")])
def test_an_out_folder_too_small_or_read_only_is_refused_before_the_model_is_built(tmp_path, options, says):
    disk = mounted_tmpfs(tmp_path / "disk", options)
    try:
        proc = run_yade(EXAMPLE, tmp_path, rmin=0.002, rmax=0.008, out=str(disk / "run"))
    finally:
        subprocess.run(["umount", str(disk)], check=True)
    assert proc.returncode != 0
    assert f"out = '{disk}/run' " in proc.stderr + proc.stdout and says in proc.stderr + proc.stdout
    assert "cross joints" not in proc.stdout  # nothing was built


def test_an_out_folder_under_a_file_is_refused_by_name(tmp_path):
    (tmp_path / "file").write_text("")
    proc = run_yade(EXAMPLE, tmp_path, rmin=0.002, rmax=0.008, out=str(tmp_path / "file" / "run"))
    assert proc.returncode != 0 and f"out = '{tmp_path}/file/run' cannot be written" in proc.stderr + proc.stdout


SMALL_RUN = dict(rmin=0.003, rmax=0.012, start_tilt=20.0, post_failure_time=0.1, checkpoint_every=1.0,
                 exact_resume=1)  # ~20 s


def outcome(summary: dict) -> dict:
    return {key: summary[key] for key in ("failure_tilt_deg", "stages", "tensile_breaks", "shear_breaks", "steps",
                                          "breaks_before_stages", "discs")}


def killed(command: list[str], env: dict, out, after: str, delay: float, saving: bool) -> bool:
    """Run ``command`` and SIGKILL it ``delay`` wall seconds after it printed a line starting
    with ``after``, or, if ``saving``, at the first checkpoint write after that; False if it
    ended first."""
    proc = subprocess.Popen(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    for line in proc.stdout:
        if line.startswith(after):
            break
    deadline = time.monotonic() + delay
    while proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.01)
    while saving and proc.poll() is None and not any(out.glob("checkpoint.saving-*.yade.bz2")):
        time.sleep(0.0005)
    if proc.poll() is not None:
        return False
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    return True


def test_a_run_killed_at_random_moments_resumes_to_the_uninterrupted_runs_result(tmp_path):
    """A tilting-table run killed with SIGKILL (on the ramp, while it writes a checkpoint, in a
    stage) and run again with the same command each time ends as the run that was never
    stopped (1 thread)."""
    (tmp_path / "straight").mkdir()
    straight = run_example(EXAMPLE, tmp_path / "straight", **SMALL_RUN)
    command, env = yade_command(EXAMPLE, tmp_path, **SMALL_RUN)
    rng = random.Random(100)
    kills = [killed(command, env, tmp_path / "out", after, rng.uniform(0.2, 3.0), saving)
             for after, saving in (("settled at", False), ("tilt ", True), ("tilt ", False))]  # ramp, stages
    assert all(kills), "the run ended before it was killed: kill it sooner"
    proc = subprocess.run(command, env=env, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    assert "resuming" in proc.stdout
    resumed = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert outcome(resumed) == outcome(straight)
