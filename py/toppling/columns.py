"""Columns of blocks standing on a table (tilting-table models, thesis §5.2): the stepped
cross-section, the main joints between columns and the cross joints inside columns.

Table frame: the table surface is y = 0, columns stand along +y, column 1 is at the toe
(face side, largest x) and columns are numbered into the slope (towards -x).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Sequence

from yade.wrapper import JointSetGeometry


@dataclass
class ColumnLayout:
    toe_x: float  # x of the face side of column 1 [m]
    width: float  # column width [m]
    heights: list[float]  # height of columns 1, 2, ... [m]

    def __post_init__(self):
        if self.width <= 0:
            raise ValueError(f"width = {self.width} is invalid: it must be > 0 m")
        if not self.heights or min(self.heights) <= 0:
            raise ValueError("heights are invalid: give at least one column, every height > 0 m")

    @classmethod
    def under_profile(cls, toe_x: float, width: float, count: int, profile: Callable[[float], float]) -> "ColumnLayout":
        """``count`` columns whose flat tops meet ``profile(distance from the toe)`` at their
        centres (rectangular blocks: a stepped face)."""
        return cls(toe_x, width, [profile((k - 0.5) * width) for k in range(1, count + 1)])

    @property
    def count(self) -> int:
        return len(self.heights)

    def span(self, k: int) -> tuple[float, float]:
        """(left, right) x of column k."""
        return self.toe_x - k * self.width, self.toe_x - (k - 1) * self.width

    def column_of(self, x: float) -> int:
        """Column of a point at x (1-based), 0 outside the columns."""
        k = math.floor((self.toe_x - x) / self.width) + 1
        return k if 1 <= k <= self.count else 0

    def section(self) -> list[tuple[float, float]]:
        """The stepped outline, counter-clockwise from the toe."""
        left_end = self.span(self.count)[0]
        outline = [(left_end, 0.0), (self.toe_x, 0.0)]
        for k, h in enumerate(self.heights, start=1):
            left, right = self.span(k)
            outline += [(right, h), (left, h)]
        return outline

    def top_centre(self, k: int) -> tuple[float, float]:
        left, right = self.span(k)
        return 0.5 * (left + right), self.heights[k - 1]

    def main_joints(self) -> JointSetGeometry:
        """Persistent vertical joints between neighbouring columns."""
        return JointSetGeometry(origin=(self.toe_x, 0), dip=90, spacing=self.width)

    def supported_height(self, k: int) -> float:
        """Height up to which column k leans on its downhill neighbour (none for column 1)."""
        return 0.0 if k == 1 else min(self.heights[k - 1], self.heights[k - 2])

    def cross_joints(self, columns: Sequence[int], spacing: float, phases: Sequence[float]) -> JointSetGeometry:
        """Joints across the given columns every ``spacing`` [m] up from ``phases[i]`` (block
        boundaries of stacked blocks), as explicit segments spanning each column, only where
        the piece above leans on the downhill neighbour over at least a quarter of a block, and
        leaves no top piece shorter than half a block. A piece standing free above its
        neighbour, touching it only at a corner, or a thin sliver on top slides off at atan(mu)
        of its joint long before the column topples (measured: the top block of column G-7,
        touching F-6 over 8 mm, and a 4 cm sliver on G-7 both slid at 28 deg)."""
        if spacing <= 0:
            raise ValueError(f"spacing = {spacing} is invalid: it must be > 0 m")
        starts, ends = [], []
        for k, phase in zip(columns, phases):
            left, right = self.span(k)
            y = phase
            while y <= self.supported_height(k) - 0.25 * spacing:
                if y > 0 and self.heights[k - 1] - y >= 0.5 * spacing:
                    starts.append((left, y))
                    ends.append((right, y))
                y += spacing
        return JointSetGeometry(dip=0, segmentStarts=starts, segmentEnds=ends)
