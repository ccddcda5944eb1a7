"""benchmarks/speed_accuracy.py: the resolution it recommends from the sizes' answers."""
from conftest import load_script

speed_accuracy = load_script("benchmarks/speed_accuracy.py")
ANSWERS = [("phi", "φ"), ("s_over_h", "S/H")]


def size(width_over_rmax: float, wall: float, phi_shift: float, phi_sd: float, sh_shift: float) -> dict:
    return {"width_over_rmax": width_over_rmax, "rmin": 1e-3, "rmax": 2e-3, "wall_time": wall,
            "phi_shift": phi_shift, "phi_sd": phi_sd, "s_over_h_shift": sh_shift, "s_over_h_sd": 0.05}


def test_the_cheapest_size_whose_every_answer_lies_within_the_finest_seed_spread_is_recommended():
    rows = [size(5, 10, -8.0, 0.0, 0.0),      # φ moved by 8° against the finest's 2° spread
            size(9, 100, 1.5, 3.0, -0.04),    # within both spreads
            size(14, 400, 0.5, 2.0, 0.06),    # S/H moved by more than 0.05
            size(20, 1000, 0.0, 2.0, 0.0)]    # the finest
    assert speed_accuracy.recommended(rows, ANSWERS).startswith("recommended: width / Rmax 9.0 (R 1–2 mm), 0.10 of")


def test_when_no_coarser_size_keeps_the_answers_the_finest_is_recommended():
    rows = [size(5, 10, -8.0, 0.0, 0.0), size(20, 1000, 0.0, 2.0, 0.0)]
    assert "the finest itself" in speed_accuracy.recommended(rows, ANSWERS)
