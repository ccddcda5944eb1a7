"""calibration/tilting_table/column_bending_spread.py: a column per seed through column_bending.py, and the table it prints."""
from conftest import load_script

spread = load_script("calibration/tilting_table/column_bending_spread.py")


def test_the_failure_tilt_is_read_from_what_column_bending_prints():
    output = ("column 50 x 300 mm, ideal rock, ...\n"
              "first bond broken (tension, 4.9 mm above the base) at 23.6 deg: ...\n"
              "failed (top moved 25 mm) at 26.3 deg: beam tension at the base 48.9 kPa (block material: 31.37 kPa)\n")
    assert spread.failure_tilt(output) == 26.3
    assert spread.row("1–4", [27.0, 25.0]) == "| 1–4 | 27.0, 25.0 | 26.0 ± 1.4 |"


def test_each_seed_packs_its_own_column_and_a_weak_short_one_breaks(capsys):
    spread.main(["13.5e3", "1-2", "0.002-0.008", "height=0.15", "rate=30"])
    row = capsys.readouterr().out.splitlines()[2]
    tilts = [float(t) for t in row.split("|")[2].split(",")]
    assert len(tilts) == 2 and tilts[0] != tilts[1] and all(0 < t < 90 for t in tilts)
