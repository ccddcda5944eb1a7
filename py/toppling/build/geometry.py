"""Slope cross-sections as YADE ``pack`` predicates (usable with ``|``, ``&``, ``-``), and
which block and layer a point lies in."""
from __future__ import annotations

from typing import Sequence

from yade import pack
from yade.wrapper import PolygonRegion

Point = Sequence[float]


def region(vertices: Sequence[Point], holes: Sequence[Sequence[Point]] = ()) -> PolygonRegion:
    """A polygon (possibly non-convex) minus holes; raises ValueError on bad polygons."""
    return PolygonRegion(vertices=[tuple(v) for v in vertices],
                         holeVertices=[tuple(v) for h in holes for v in h],
                         holeSizes=[len(h) for h in holes])


class PolygonPredicate(pack.Predicate):
    """A PolygonRegion as a YADE predicate: prism through z in [-zHalf, zHalf]."""

    def __init__(self, polygon: PolygonRegion, z_half: float = 1.0):
        pack.Predicate.__init__(self)
        self.polygon, self.z_half = polygon, z_half

    def __call__(self, pt, pad=0.0):
        return abs(pt[2]) <= self.z_half - pad and self.polygon.contains((pt[0], pt[1]), pad)

    def aabb(self):
        lo, hi = self.polygon.aabb()
        return (lo[0], lo[1], -self.z_half), (hi[0], hi[1], self.z_half)

    def dim(self):
        lo, hi = self.aabb()
        return tuple(h - l for h, l in zip(hi, lo))

    def center(self):
        lo, hi = self.aabb()
        return tuple((h + l) / 2 for h, l in zip(hi, lo))
