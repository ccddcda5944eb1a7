"""scripts/plot_seed_spread.py on made-up summaries: which models it draws, and that it writes the PNG."""
import json

import pytest

from conftest import load_script

plot = load_script("plot_seed_spread")


def summary(rmax: float, seed: int, tilt, wall: float, strength: float = 55e3) -> dict:
    inputs = {"arrangement": "ideal", "rmin": 1e-3, "rmax": rmax, "bond_tensile_strength": strength,
              "main_joint_friction": 0.0, "base_joint_friction": 0.0, "seed": seed}
    return {"inputs": inputs, "failure_tilt_deg": tilt, "phi_deg": [15.0], "wall_time": wall,
            "thesis": {"failure_tilt_deg": 35, "phi_deg": [15]}}


def runs() -> dict[str, dict]:
    return {"coarse_s1": summary(4e-3, 1, 36.0, 1900.0), "coarse_s2": summary(4e-3, 2, 30.0, 1300.0),
            "fine_s1": summary(2.5e-3, 1, 42.0, 13000.0),
            "fine_s2": {**summary(2.5e-3, 2, None, 9000.0), "stable_up_to_deg": 44.0},
            "lonely": summary(4e-3, 1, 32.0, 2000.0, strength=65e3)}


def test_a_model_with_several_seeds_is_drawn_with_its_other_sizes_and_a_single_run_model_is_not():
    models = plot.sized_groups(runs())
    assert len(models) == 1
    (sizes,) = models.values()
    assert sorted(key[-4] for key in sizes) == [2.5e-3, 4e-3]


def test_the_figure_is_written(tmp_path, capsys):
    for name, s in runs().items():
        (tmp_path / name).mkdir()
        (tmp_path / name / "summary.json").write_text(json.dumps(s))
    plot.main(str(tmp_path), str(tmp_path / "spread.png"))
    assert (tmp_path / "spread.png").stat().st_size > 10_000
    with pytest.raises(SystemExit, match="several seeds or layouts"):
        plot.main(str(tmp_path / "lonely"), str(tmp_path / "none.png"))


def test_the_random_arrangement_is_drawn_over_its_packing_and_layout_seeds():
    layouts = {f"l{layout}": summary(4e-3, 1, tilt, 3000.0) for layout, tilt in ((1, 19.0), (2, 17.0), (3, 19.0))}
    for layout, s in enumerate(layouts.values(), start=1):
        s["inputs"].update(arrangement="random", layout_seed=layout)
    (sizes,) = plot.sized_groups(layouts).values()
    assert [len(group) for group in sizes.values()] == [3]
