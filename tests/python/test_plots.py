"""The slope figures: the model's outline in view, not discs that fell off it; the model's joints by set."""
import numpy as np
import pytest
from matplotlib import image

from toppling.analyse import failure
from toppling.io import plots


def test_around_widens_the_box_by_a_share_of_its_larger_side():
    outline = np.array([(0.0, 0.0), (0.8, 0.0), (0.8, 0.4), (0.0, 0.4)])
    assert plots.around(outline, 0.1) == pytest.approx((-0.08, 0.88, -0.08, 0.48))


def test_outside_counts_the_centres_beyond_the_limits():
    centres = np.array([(0.1, 0.1), (0.5, 0.3), (0.6, -12.0), (2.0, 0.2)])
    assert plots.outside(centres, (0.0, 1.0, 0.0, 0.5)) == 2


def test_a_fallen_disc_does_not_shrink_the_slope_to_a_dot(tmp_path):
    """With the limits of the outline the discs fill the picture as when none had fallen."""
    grid = np.array([(x, y) for x in np.arange(0.005, 0.4, 0.01) for y in np.arange(0.005, 0.2, 0.01)])
    fallen = np.vstack([grid, [(0.45, -30.0)]])
    view = plots.around(np.array([(0, 0), (0.4, 0), (0.4, 0.2), (0, 0.2)]), 0.15)

    def drawn_share(centres, name):
        path = plots.slope(str(tmp_path), name, centres, [0.005] * len(centres), np.zeros_like(centres),
                           [], [], limits=view)
        rgb = image.imread(path)[..., :3]
        return float((rgb.sum(axis=2) < 2.5).mean())  # discs (grey where nothing moved) and the axes' ink

    assert drawn_share(fallen, "fallen") == pytest.approx(drawn_share(grid, "standing"), rel=0.1)


def test_the_overall_surface_is_drawn_dashed_beside_the_two_it_splits_into(tmp_path):
    """The dog-leg of a toe segment along the table and a 45 degree one: the overall line runs
    between them and darkens pixels neither of them does."""
    points = [(-0.05 * k, 0.05 * max(0, k - 3)) for k in range(8)]
    planes, overall = failure.fit_failure_surface(points), failure.overall_surface(points)
    centres = np.array([(0.5, 0.5)])
    view = (-0.4, 0.05, -0.05, 0.3)

    def dark(name, **kw):
        path = plots.slope(str(tmp_path), name, centres, [0.001], np.zeros_like(centres), [], [], planes,
                           limits=view, **kw)
        assert path.endswith(f"{name}.png")
        return float((image.imread(path)[..., :3].sum(axis=2) < 0.5).sum())

    assert len(planes) == 2 and dark("with", overall=overall) > dark("without") + 50


def test_the_model_picture_draws_each_joint_set_in_its_colour_and_marks_the_fixed_discs(tmp_path):
    centres = np.array([(x, y) for x in np.arange(0.005, 0.2, 0.01) for y in np.arange(0.005, 0.1, 0.01)])
    joints = [((0.1, 0.0), (0.1, 0.1), 0), ((0.0, 0.05), (0.2, 0.05), 1)]  # a main joint and a cross joint
    held = centres[:, 1] < 0.01
    path = plots.model(str(tmp_path), "model", centres, [0.005] * len(centres), np.zeros_like(centres), held,
                       joints, ("main joints", "cross joints"), limits=(-0.02, 0.22, -0.02, 0.12))
    rgb = image.imread(path)[..., :3]
    orange = (rgb[..., 0] > 0.9) & (rgb[..., 1] > 0.4) & (rgb[..., 1] < 0.7) & (rgb[..., 2] < 0.2)
    assert orange.sum() > 50  # the cross joint's set, drawn darkorange


def test_zone_labels_of_many_columns_mark_where_the_zone_changes():
    few = [(k, 0.0, "toppling") for k in range(5)]
    assert plots.zone_labels(few) == few
    many = [(k, 0.0, "sliding" if k < 3 else "toppling" if k < 40 else "no-movement") for k in range(80)]
    assert plots.zone_labels(many) == [(0, 0.0, "sliding"), (3, 0.0, "toppling"), (40, 0.0, "no-movement")]
