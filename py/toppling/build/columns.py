"""Columns of blocks standing on a table (tilting-table models, thesis §5.2): the stepped
cross-section, the main joints between columns and the cross joints inside columns.

Table frame: the table surface is y = 0, columns stand along +y, column 1 is at the toe
(face side, largest x) and columns are numbered into the slope (towards -x).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Mapping, Sequence

import numpy as np
from yade.wrapper import JointSetGeometry

from toppling.checks import require


@dataclass
class ColumnLayout:
    toe_x: float  # x of the face side of column 1 [m]
    width: float  # column width [m]
    heights: list[float]  # height of columns 1, 2, ... [m]

    def __post_init__(self):
        require("width", self.width, "(0, inf)")
        if not self.heights:
            raise ValueError("heights = [] is invalid: give at least one column's height")
        for k, height in enumerate(self.heights):
            require(f"heights[{k}]", height, "(0, inf)")

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

    def columns_of(self, points: np.ndarray, floor: float) -> np.ndarray:
        """Column of each xy point (1-based), 0 outside the columns or below height ``floor``
        (a disc that dropped off the table is no column's)."""
        points = np.asarray(points, dtype=float)
        column = np.array([self.column_of(x) for x in points[:, 0]], dtype=int)
        column[points[:, 1] <= floor] = 0
        return column

    def section(self) -> list[tuple[float, float]]:
        """The stepped outline, counter-clockwise from the toe."""
        left_end = self.span(self.count)[0]
        outline = [(left_end, 0.0), (self.toe_x, 0.0)]
        for k, h in enumerate(self.heights, start=1):
            left, right = self.span(k)
            outline += [(right, h), (left, h)]
        return outline

    def far_edges(self, tilt_deg: float) -> list[float]:
        """Horizontal distance from the toe to each column's far top corner, the table tilted
        by ``tilt_deg`` towards the toe (thesis §5.3.3.2: the S and T of S/H, T/H)."""
        a = math.radians(tilt_deg)
        return [k * self.width * math.cos(a) - h * math.sin(a) for k, h in enumerate(self.heights, start=1)]

    def crest_height(self, tilt_deg: float) -> float:
        """Height H of the slope that the columns make on a table tilted by ``tilt_deg``: of its
        crest, the top centre of the tallest column, above the toe (the thesis' H, e.g. Table 5-2's
        47.39 cm; a top surface rising behind the crest, as at β = 8°, does not count)."""
        a = math.radians(tilt_deg)
        x, y = self.top_centre(1 + self.heights.index(max(self.heights)))
        return -math.sin(a) * (x - self.toe_x) + math.cos(a) * y

    def top_centre(self, k: int) -> tuple[float, float]:
        left, right = self.span(k)
        return 0.5 * (left + right), self.heights[k - 1]

    def main_joints(self) -> JointSetGeometry:
        """Persistent vertical joints between neighbouring columns."""
        return JointSetGeometry(origin=(self.toe_x, 0), dip=90, spacing=self.width)

    def supported_height(self, k: int) -> float:
        """Height up to which column k leans on its downhill neighbour (none for column 1)."""
        return 0.0 if k == 1 else min(self.heights[k - 1], self.heights[k - 2])

    def stacked_blocks(self, k: int, length: float, phase: float) -> list[float]:
        """Heights of the boundaries between blocks of ``length`` [m] stacked in column k, the
        first at ``phase`` (0 <= phase < length; 0: the lowest block stands on the table)."""
        require("length", length, "(0, inf)")
        require("phase", phase, f"[0, {length})")
        count = math.ceil((self.heights[k - 1] - phase) / length)
        return [phase + i * length for i in range(max(count, 0)) if phase + i * length > 0]

    def cross_joints(self, cuts: Mapping[int, Sequence[float]], block_length: float,
                     every_cut: bool = False) -> JointSetGeometry:
        """Joints across columns k at heights ``cuts[k]`` [m], as explicit segments spanning each
        column, kept only where the piece above leans on the downhill neighbour over at least a
        quarter of ``block_length`` and leaves no top piece shorter than half of it. A piece
        standing free above its neighbour, touching it only at a corner, or a thin sliver on
        top slides off at atan(mu) of its joint long before the column topples (measured: the
        top block of column G-7, touching F-6 over 8 mm, and a 4 cm sliver on G-7 both slid at
        28 deg). With ``every_cut`` every cut inside a column is a joint: the blocks as stacked,
        rules off."""
        require("block_length", block_length, "(0, inf)")
        starts, ends = [], []
        for k, heights in cuts.items():
            left, right = self.span(k)
            for y in heights:
                leans = y <= self.supported_height(k) - 0.25 * block_length
                kept = leans and self.heights[k - 1] - y >= 0.5 * block_length
                if 0 < y < self.heights[k - 1] and (kept or every_cut):
                    starts.append((left, y))
                    ends.append((right, y))
        return JointSetGeometry(dip=0, segmentStarts=starts, segmentEnds=ends)
