"""Monitoring points: displacement histories of labelled discs (column tops)."""
from __future__ import annotations

import math
from typing import Any, Optional, Sequence

from yade import O

from toppling.analyse import failure
from toppling.build import columns


class MonitoringPoints:
    """Displacement histories (X, Y, total) of labelled discs, e.g. column tops ``G-7``."""

    def __init__(self, labels: Sequence[str], ids: Sequence[int]):
        self.labels, self.ids = list(labels), list(ids)
        self.reference = [tuple(O.bodies[i].state.pos) for i in self.ids]
        self.time: list[float] = []
        self.x: dict[str, list[float]] = {label: [] for label in self.labels}
        self.y: dict[str, list[float]] = {label: [] for label in self.labels}

    def record(self) -> None:
        self.time.append(O.time)
        for label, i, ref in zip(self.labels, self.ids, self.reference):
            p = O.bodies[i].state.pos
            self.x[label].append(p[0] - ref[0])
            self.y[label].append(p[1] - ref[1])

    def total(self, label: str) -> list[float]:
        return [(dx * dx + dy * dy) ** 0.5 for dx, dy in zip(self.x[label], self.y[label])]

    def displacement(self, label: str, turn_deg: float = 0.0, x_into_slope: bool = False) -> tuple[list[float], list[float]]:
        """X and Y of the point's displacement since the start: the scene's turned by
        ``turn_deg`` clockwise (a table tilted by it made level: the world's horizontal and
        vertical), X pointing the other way with ``x_into_slope`` (as the thesis draws a slope,
        face on the left)."""
        a = math.radians(turn_deg)
        c, s, sign = math.cos(a), math.sin(a), -1.0 if x_into_slope else 1.0
        return ([sign * (c * dx + s * dy) for dx, dy in zip(self.x[label], self.y[label])],
                [-s * dx + c * dy for dx, dy in zip(self.x[label], self.y[label])])

    def direction(self, label: str, still: float, turn_deg: float = 0.0, x_into_slope: bool = False) -> list[float]:
        """Y/X, the direction of the point's displacement since the start (the thesis' dY/dX,
        Fig 5-21 c: a steady value is a steady sense of motion) in the frame of ``displacement``;
        NaN while the point has moved less than ``still`` [m], where the ratio of two
        round-off-sized numbers is noise."""
        x, y = self.displacement(label, turn_deg, x_into_slope)
        return [dy / dx if dx != 0 and (dx * dx + dy * dy) ** 0.5 >= still else math.nan for dx, dy in zip(x, y)]

    def rate_since(self, label: str, since: float, until: Optional[float] = None) -> float:
        """How fast [m/s] the point's total displacement changed from the record nearest the
        simulated time ``since`` to the one nearest ``until`` (the last record by default; 0 with
        no time between): a column still toppling keeps moving, one that only rattles does not."""
        start, end = (min(range(len(self.time)), key=lambda i: abs(self.time[i] - t)) for t in (since, until or self.time[-1]))
        span = self.time[end] - self.time[start]
        total = self.total(label)
        return abs(total[end] - total[start]) / span if span > 0 else 0.0

    def as_dict(self) -> dict[str, Any]:
        return {"labels": self.labels, "ids": self.ids, "reference": self.reference, "time": self.time,
                "x": self.x, "y": self.y}

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> "MonitoringPoints":
        points = cls.__new__(cls)
        points.labels, points.ids = d["labels"], d["ids"]
        points.reference = [tuple(r) for r in d["reference"]]
        points.time, points.x, points.y = d["time"], d["x"], d["y"]
        return points


def column_top_points(layout: columns.ColumnLayout, ids: Sequence[int]) -> MonitoringPoints:
    """Monitoring points at the column tops, labelled as in the thesis (``G-7``): of ``ids``,
    the disc nearest each column's top centre. A column holding none of them (at coarse
    resolution a toe column a few discs high can come out of the packing empty) has no
    point, and the console says so."""
    nearest: dict[int, tuple[float, int]] = {}
    for i in ids:
        x, y = tuple(O.bodies[i].state.pos)[:2]
        k = layout.column_of(x)
        if k:
            cx, cy = layout.top_centre(k)
            distance = (x - cx) ** 2 + (y - cy) ** 2
            nearest[k] = min(nearest.get(k, (distance, i)), (distance, i))
    for k in range(1, layout.count + 1):
        if k not in nearest:
            print(f"column {failure.column_label(k)}: no discs, no monitoring point")
    ordered = sorted(nearest)
    return MonitoringPoints([failure.column_label(k) for k in ordered], [nearest[k][1] for k in ordered])
