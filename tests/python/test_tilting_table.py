"""The tilting-table example stops on bad parameters with a message naming them, before it builds anything."""
import os
import subprocess

import pytest
from conftest import run_yade

EXAMPLE = "examples/tilting_table/run.py"


@pytest.mark.parametrize("params", [dict(start_tilt=-1.0), dict(start_tilt=50.0, max_tilt=45.0),
                                    dict(step=0.0), dict(tilt_rate=0.0), dict(max_tilt=90.0)])
def test_bad_tilt_parameters_stop_before_the_model_is_built(tmp_path, params):
    proc = run_yade(EXAMPLE, tmp_path, rmin=0.002, rmax=0.008, **params)
    assert proc.returncode != 0
    assert "0 <= start_tilt <= max_tilt < 90 deg" in proc.stderr + proc.stdout
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("name, value, valid", [("timestep_safety", 0.0, "in (0, 1]"), ("timestep_safety", 1.5, "in (0, 1]"),
                                               ("joint_stiffness_scale", 0.0, "in (0, 1]"),
                                               ("joint_stiffness_scale", 2.0, "in (0, 1]"),
                                               ("bond_gap", 0.01, "in (0, rmax] m"),
                                               ("damping", 1.0, "in [0, 1)"), ("settle_damping", -0.1, "in [0, 1)"),
                                               ("stage_rate", -1.0, "0 (each step at once) or > 0 deg/s"),
                                               ("layout_seed", 1.5, "an integer >= 0"),
                                               ("cut_rules", 2, "0 or 1"), ("joint_pieces", 2, "0 or 1"),
                                               ("z_order", 2, "0 or 1"),
                                               ("bond_tensile_strength", 300e3, "0 (the thesis' table) or in its "
                                                                                "range [13500, 209000]"),
                                               ("arrest_time", -1.0, "0 (the first failing stage is the failure) or > 0 s"),
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
