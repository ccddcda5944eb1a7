"""Cross-section predicates, joint-set geometry and the 2D packer, through YADE's Python."""
import math
import random

import pytest
from yade import pack
from yade.wrapper import JointSetGeometry

from toppling.build import geometry, packing

L_SHAPE = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]


def test_polygon_region_area_containment_and_holes():
    l_shape = geometry.region(L_SHAPE)
    assert l_shape.area() == pytest.approx(3.0)
    assert l_shape.contains((0.5, 1.5)) and not l_shape.contains((1.5, 1.5))
    square_with_hole = geometry.region([(0, 0), (10, 0), (10, 10), (0, 10)], holes=[[(4, 4), (6, 4), (6, 6), (4, 6)]])
    assert square_with_hole.area() == pytest.approx(96.0)
    assert not square_with_hole.contains((5, 5)) and not square_with_hole.contains((3.5, 5), 1.0)


@pytest.mark.parametrize("vertices, message", [
    ([(0, 0), (1, 1), (1, 0), (0, 1)], "self-intersecting"),
    ([(0, 0), (1, 0)], "at least 3 vertices"),
])
def test_bad_polygons_are_rejected(vertices, message):
    with pytest.raises(ValueError, match=message):
        geometry.region(vertices)


def test_predicates_combine_with_yade_pack_operators():
    a = geometry.PolygonPredicate(geometry.region(L_SHAPE))
    b = geometry.PolygonPredicate(geometry.region([(1.5, 0), (3, 0), (3, 3), (1.5, 3)]))
    assert (a | b)((2.5, 2.5, 0)) and not a((2.5, 2.5, 0))
    assert (a & b)((1.8, 0.5, 0)) and not (a & b)((0.5, 0.5, 0))
    assert (a - b)((0.5, 0.5, 0)) and not (a - b)((1.8, 0.5, 0))
    assert isinstance(a | b, pack.Predicate)


def test_joint_set_geometry_and_bad_spacing():
    joints = JointSetGeometry(origin=(0, 0), dip=90, spacing=0.1)
    assert len(joints.segments((-0.05, 0), (0.95, 1))) == 10  # x = 0, 0.1, ..., 0.9
    assert joints.band((0.25, 0.5)) == -3  # normal (-1, 0): bands count towards -x
    with pytest.raises(ValueError, match="spacing"):
        JointSetGeometry(spacing=-1.0)


def test_the_band_of_a_point_tells_layers_and_blocks_apart():
    columns = JointSetGeometry(origin=(0, 0), dip=80, spacing=0.1)  # main joints, dipping 80 deg
    bedding = JointSetGeometry(origin=(0, 0), dip=0, spacing=0.3)  # layers 0.3 m thick
    assert bedding.band((0.0, 0.1)) != bedding.band((0.0, 0.4))
    assert bedding.band((0.0, 0.1)) == bedding.band((5.0, 0.2))

    def block(p):
        return columns.band(p), bedding.band(p)

    assert block((0.05, 0.1)) == block((0.06, 0.12))
    assert block((0.2, 0.1)) != block((0.05, 0.1))  # across a main joint
    assert block((0.05, 0.35)) != block((0.05, 0.1))  # across a bedding plane


def test_packer_is_reproducible_and_meets_its_targets(empty_scene):
    square = geometry.region([(0, 0), (0.05, 0), (0.05, 0.05), (0, 0.05)])
    first = packing.pack_polygon(square, 1e-3, 2.5e-3, porosity=0.2, seed=7)
    again = packing.pack_polygon(square, 1e-3, 2.5e-3, porosity=0.2, seed=7)
    assert first.discs == again.discs
    assert first.porosity == pytest.approx(0.2, abs=0.01)
    assert all(square.containsMany([(x, y) for x, y, _ in first.discs], 0.0))
    assert first.mean_overlap < 0.01 * 1e-3
    assert len(first.discs) == pytest.approx(0.8 * 0.05**2 / (math.pi * (2.5e-3**3 - 1e-3**3) / (3 * 1.5e-3)), abs=1)


def _overlap(a, b):
    return a[2] + b[2] - math.dist(a[:2], b[:2])


def test_pairs_within_finds_exactly_the_pairs_a_brute_force_search_finds():
    rng = random.Random(3)
    discs = [(rng.uniform(0, 0.05), rng.uniform(0, 0.05), rng.uniform(1e-3, 4e-3)) for _ in range(300)]
    gap = 5e-4
    expected = {(i, j) for i in range(len(discs)) for j in range(i + 1, len(discs)) if _overlap(discs[i], discs[j]) >= -gap}
    found = [(i, j) for i, j, _ in packing.pairs_within([d[:2] for d in discs], [d[2] for d in discs], gap)]
    assert len(found) == len(set(found)) and set(found) == expected


def test_z_order_visits_cells_in_morton_order():
    cells = [(ix, iy) for iy in range(4) for ix in range(4)]
    random.Random(2).shuffle(cells)
    ordered = packing.z_order([(ix + 0.5, iy + 0.5, 0.5) for ix, iy in cells])  # one disc per cell of a diameter
    assert [(x - 0.5, y - 0.5) for x, y, _ in ordered] == [
        (0, 0), (1, 0), (0, 1), (1, 1), (2, 0), (3, 0), (2, 1), (3, 1),
        (0, 2), (1, 2), (0, 3), (1, 3), (2, 2), (3, 2), (2, 3), (3, 3)]


def test_z_order_keeps_the_discs_and_brings_neighbours_near():
    rng = random.Random(7)
    discs = [(rng.uniform(0, 0.2), rng.uniform(0, 0.2), rng.uniform(1e-3, 2.5e-3)) for _ in range(3000)]
    ordered = packing.z_order(discs)
    assert sorted(ordered) == sorted(discs)

    def mean_id_distance(ds):
        pairs = list(packing.pairs_within([d[:2] for d in ds], [d[2] for d in ds], 1e-3))
        return sum(j - i for i, j, _ in pairs) / len(pairs)
    # random ids: about N/3 apart (1001 here); along the curve 36, the jumps between quadrants included
    assert mean_id_distance(discs) > 900 and mean_id_distance(ordered) < 50
    assert packing.z_order([]) == []


def test_shrink_overlaps_leaves_no_overlap_and_shrinks_by_half_the_largest():
    two = packing.shrink_overlaps([(0, 0, 1.0), (1.8, 0, 1.0), (5, 0, 1.0)])  # overlap 0.2; a third apart
    assert two == [(0, 0, pytest.approx(0.9)), (1.8, 0, pytest.approx(0.9)), (5, 0, 1.0)]
    rng = random.Random(5)
    discs = [(rng.uniform(0, 0.05), rng.uniform(0, 0.05), rng.uniform(1e-3, 4e-3)) for _ in range(300)]
    shrunk = packing.shrink_overlaps(discs)
    worst = max(_overlap(a, b) for k, a in enumerate(shrunk) for b in shrunk[k + 1:])
    assert worst <= 1e-15  # touching at most
    for k, (disc, after) in enumerate(zip(discs, shrunk)):  # no disc shrinks more than it must
        largest = max([_overlap(disc, other) for m, other in enumerate(discs) if m != k] + [0.0])
        assert disc[2] - after[2] == pytest.approx(0.5 * largest, abs=1e-15)


def test_a_combined_yade_predicate_is_packed_with_discs_wholly_inside_it(empty_scene):
    outline = [(0, 0), (0.1, 0), (0.1, 0.1), (0, 0.1)]
    tunnel = pack.inCylinder((0.05, 0.05, -1), (0.05, 0.05, 1), 0.03)  # a hole through the plane
    packed = packing.pack_predicate(geometry.PolygonPredicate(geometry.region(outline)) - tunnel, 0.002, 0.004, 0.18,
                                    seed=3)

    def inside(x, y, r):  # in the square and clear of the tunnel, by plain geometry
        return r <= x <= 0.1 - r and r <= y <= 0.1 - r and math.hypot(x - 0.05, y - 0.05) >= 0.03 + r

    box = packing.pack_polygon(geometry.region(outline), 0.002, 0.004, 0.18, seed=3).discs  # the bounding box's
    assert packed.discs == [d for d in box if inside(*d)] and len(packed.discs) > 0.4 * len(box)


def test_a_kept_packing_is_read_back_to_the_last_bit(tmp_path, monkeypatch):
    """keep=True: the second call reads the first's discs back (the same floats) without packing;
    other inputs make another packing."""
    monkeypatch.setenv("TOPPLING_CACHE", str(tmp_path))
    square = geometry.region([(0, 0), (0.05, 0), (0.05, 0.05), (0, 0.05)])
    first = packing.pack_polygon(square, 0.002, 0.004, 0.25, seed=3, keep=True)
    again = packing.pack_polygon(square, 0.002, 0.004, 0.25, seed=3, keep=True)
    assert first.seconds > 0 and again.seconds == 0.0
    assert again.discs == first.discs and again.porosity == first.porosity
    assert packing.pack_polygon(square, 0.002, 0.004, 0.25, seed=3).discs == first.discs  # what is kept is the packing
    assert packing.pack_polygon(square, 0.002, 0.004, 0.25, seed=4, keep=True).discs != first.discs
    assert len(list(tmp_path.glob("packings/*.json"))) == 2
