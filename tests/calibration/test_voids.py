"""calibration/ihlara/voids.py: where a packing is loose, by sliding windows and empty circles."""
import math
from types import SimpleNamespace

import numpy as np
from conftest import load_script

voids = load_script("calibration/ihlara/voids.py")
R = 0.1


def lattice_with_a_hole(hole: tuple[float, float], hole_radius: float) -> np.ndarray:
    """Discs of radius R on a square lattice (solid fraction π/4) filling x 0-10, y -4-6, none
    whose centre lies within ``hole_radius`` of ``hole``."""
    xs, ys = np.meshgrid(np.arange(R, 10, 2 * R), np.arange(-4 + R, 6, 2 * R))
    keep = np.hypot(xs - hole[0], ys - hole[1]) > hole_radius
    return np.column_stack([xs[keep], ys[keep], np.full(keep.sum(), R)])


def test_the_loosest_window_and_the_largest_empty_circle_are_at_the_hole():
    cliff = SimpleNamespace(rmax=R, foundation=SimpleNamespace(top=4.0), height=6.0, face_x=10.0, width=10.0)
    discs = lattice_with_a_hole((6.0, 2.0), 0.5)
    found = voids.windows(discs, cliff, 1.4)
    fractions = [w[2] for w in found]
    assert abs(np.median(fractions) - math.pi / 4) < 0.02
    left, bottom, loosest = min(found, key=lambda w: w[2])
    assert left < 6.0 < left + 1.4 and bottom < 2.0 < bottom + 1.4
    assert loosest < math.pi / 4 - 0.2  # the hole takes some 20 of the window's 49 discs
    x, y, room = voids.largest_hole(discs, (1.0, 9.0, -3.0, 5.0))
    assert math.hypot(x - 6.0, y - 2.0) < 0.1 and 0.4 < room < 0.6  # its centre, and room up to the next discs
