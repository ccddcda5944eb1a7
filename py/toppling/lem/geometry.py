"""A toppling slope's geometry and the columns the limit-equilibrium methods cut it into.

Coordinates: the toe at the origin, x horizontal into the slope, y up. The face rises from the
toe at ``face_deg`` to the crest, ``height`` above the toe; the top surface rises from the crest
at ``top_deg``. The main joints (the columns' sides) dip ``joint_dip_deg`` into the slope and
are ``spacing`` apart; the columns' bases step up along a line through the toe
``failure_plane_deg`` above the normal to the joints (Goodman and Bray's base line, Aydan and
Kawamoto's fracture plane, the thesis' φ).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from toppling.checks import require
from toppling.lem.goodman_bray import Blocks


@dataclass(frozen=True)
class SlopeGeometry:
    height: float  # m
    face_deg: float
    top_deg: float
    joint_dip_deg: float
    failure_plane_deg: float
    spacing: float  # m

    def __post_init__(self):
        require("height", self.height, "(0, inf)")
        require("spacing", self.spacing, "(0, inf)")
        require("joint_dip_deg", self.joint_dip_deg, "(0, 90)")
        require("failure_plane_deg", self.failure_plane_deg, f"[0, {self.joint_dip_deg:g})")  # below the joints
        # a face no steeper than the base line leaves no column standing on it to topple
        require("face_deg", self.face_deg, f"({self.base_dip_deg + self.failure_plane_deg:g}, 90)")
        require("top_deg", self.top_deg, f"[0, {self.base_dip_deg:g})")  # flatter than the joints' normal: the slope ends

    @classmethod
    def from_slope_shape(cls, failure_plane_deg: float, *, height: float, joint_dip_deg: float, face_deg: float,
                         top_deg: float, spacing: float) -> "SlopeGeometry":
        """The geometry of a ``toppling.models.equivalent_slope.SlopeShape`` (its fields as keywords),
        whose face angle θ is measured from the horizontal behind the face as the thesis' (§5.3.1):
        the face dips 180° − θ."""
        return cls(height=height, face_deg=180.0 - face_deg, top_deg=top_deg, joint_dip_deg=joint_dip_deg,
                   failure_plane_deg=failure_plane_deg, spacing=spacing)

    @property
    def base_dip_deg(self) -> float:
        """ψp: the dip of the columns' bases, normal to the main joints."""
        return 90.0 - self.joint_dip_deg

    def blocks(self, unit_weight: float) -> Blocks:
        """Goodman and Bray's blocks, discretised as Hoek and Bray (1981): a1 = Δx tan(ψf − ψp),
        a2 = Δx tan(ψp − ψs), b = Δx tan(ψb − ψp); block n below the crest is n (a1 − b) high,
        above it each block is a2 + b lower than the one before, until none is left; the crest
        block is the one whose width holds the crest."""
        dx, psi_p = self.spacing, math.radians(self.base_dip_deg)
        a1 = dx * math.tan(math.radians(self.face_deg) - psi_p)
        a2 = dx * math.tan(psi_p - math.radians(self.top_deg))
        b = dx * math.tan(math.radians(self.failure_plane_deg))
        crest_x = self.height / math.tan(math.radians(self.face_deg))
        crest = math.ceil((crest_x * math.cos(psi_p) + self.height * math.sin(psi_p)) / dx - 1e-9)
        heights = [n * (a1 - b) for n in range(1, crest + 1)]
        while heights[-1] - a2 - b > 0:
            heights.append(heights[-1] - a2 - b)
        return Blocks(tuple(heights), dx, self.base_dip_deg, a1, a2, unit_weight, crest=crest)

    def side_lengths(self) -> list[float]:
        """The length of each main joint from the failure plane up to the slope's surface, from
        the toe (0) to the first joint that meets the failure plane above the surface (0 too)."""
        delta, theta = math.radians(self.joint_dip_deg), math.radians(self.failure_plane_deg)
        plane = math.radians(self.base_dip_deg) + theta
        up = (-math.cos(delta), math.sin(delta))  # along a joint, up and out of the slope
        lengths = [0.0]
        for j in range(1, 100_000):
            along = j * self.spacing / math.cos(theta)
            start = (along * math.cos(plane), along * math.sin(plane))
            length = self._to_surface(start, up)
            lengths.append(length)
            if length == 0:
                return lengths
        raise ValueError("the slope holds more than 100000 columns: check spacing against height")

    def _to_surface(self, start: tuple[float, float], up: tuple[float, float]) -> float:
        """Distance from ``start`` along ``up`` to the surface, 0 if ``start`` is not below it. The
        surface is the lower of the face and top lines (the face is the steeper), so the ray
        leaves the slope where it crosses the first of them."""
        crest_x = self.height / math.tan(math.radians(self.face_deg))
        distances = []
        for (x0, y0), slope in (((0.0, 0.0), math.tan(math.radians(self.face_deg))),
                                ((crest_x, self.height), math.tan(math.radians(self.top_deg)))):
            gap = y0 + slope * (start[0] - x0) - start[1]
            if gap <= 0:
                return 0.0
            distances.append(gap / (up[1] - slope * up[0]))
        return min(distances)
