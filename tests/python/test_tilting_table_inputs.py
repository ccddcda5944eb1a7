"""The tilting-table example stops on bad tilt and time-step parameters with a message naming them."""
import pytest
from conftest import run_yade


@pytest.mark.parametrize("params", [dict(start_tilt=-1.0), dict(start_tilt=50.0, max_tilt=45.0),
                                    dict(step=0.0), dict(tilt_rate=0.0), dict(max_tilt=90.0)])
def test_bad_tilt_parameters_stop_before_the_model_is_built(tmp_path, params):
    proc = run_yade("examples/tilting_table.py", tmp_path, rmin=0.002, rmax=0.008, **params)
    assert proc.returncode != 0
    assert "0 <= start_tilt <= max_tilt < 90 deg" in proc.stderr + proc.stdout
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("safety", [0.0, 1.5])
def test_a_time_step_safety_outside_0_1_stops_the_run(tmp_path, safety):
    proc = run_yade("examples/tilting_table.py", tmp_path, rmin=0.002, rmax=0.008, timestep_safety=safety)
    assert proc.returncode != 0
    assert f"timestep_safety = {safety} is invalid: it must be in (0, 1]" in proc.stderr + proc.stdout
    assert not (tmp_path / "out").exists()


def test_shrink_overlaps_other_than_0_or_1_stops_the_run(tmp_path):
    proc = run_yade("examples/tilting_table.py", tmp_path, rmin=0.002, rmax=0.008, shrink_overlaps=2)
    assert proc.returncode != 0
    assert "shrink_overlaps = 2 is invalid: it must be 0 or 1" in proc.stderr + proc.stdout
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("scale", [0.0, 2.0])
def test_a_joint_stiffness_scale_outside_0_1_stops_the_run(tmp_path, scale):
    proc = run_yade("examples/tilting_table.py", tmp_path, rmin=0.002, rmax=0.008, joint_stiffness_scale=scale)
    assert proc.returncode != 0
    assert f"joint_stiffness_scale = {scale} is invalid: it must be in (0, 1]" in proc.stderr + proc.stdout
    assert not (tmp_path / "out").exists()
