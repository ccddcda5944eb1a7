"""PNG figures every slope case writes: the model (joints by set, fixed discs, the displacement
at rest), the slope coloured by displacement with cracks, the fitted failure surface and the
zones, the loading history, and monitoring-point histories (Fig 5-21 style)."""
from __future__ import annotations

from typing import Optional, Sequence

from toppling.io import output  # first: it selects matplotlib's headless backend

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import EllipseCollection  # noqa: E402
from toppling.analyse.failure import Plane
from toppling.run.monitoring import MonitoringPoints


SLOPE_SIZE = (9, 5.5)  # [in]: a slope wider than high, its legend below it
ZONE_COLOURS = {"no-movement": "0.5", "stable": "green", "toppling": "red", "sliding": "blue", "empty": "0.8"}
SET_COLOURS = ("black", "darkorange", "purple", "teal")


def _discs(ax, fig, centres: np.ndarray, radii: Sequence[float], displacement: np.ndarray, what: str) -> None:
    """Discs coloured by |displacement| [mm] up to its 99th percentile (a few escaped discs must
    not wash out the field), or plain grey with a note where nothing moved."""
    radii = np.asarray(radii)
    magnitude = 1e3 * np.linalg.norm(displacement, axis=1)
    moved = magnitude.size and np.percentile(magnitude, 99) > 1e-6
    colours = dict(array=magnitude, cmap="viridis") if moved else dict(facecolors="0.75")
    discs = EllipseCollection(2 * radii, 2 * radii, np.zeros_like(radii), units="xy", offsets=centres,
                              transOffset=ax.transData, **colours)
    ax.add_collection(discs)
    if moved:
        discs.set_clim(0, np.percentile(magnitude, 99))
        fig.colorbar(discs, ax=ax, label=f"{what} (mm), 99th percentile at the top", extend="max")
    else:
        ax.text(0.01, 0.95, f"{what}: none", transform=ax.transAxes, fontsize=7)


def _legend(ax) -> None:
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=3, fontsize=8, frameon=False)


def _view(ax, centres: np.ndarray, limits: Optional[tuple[float, float, float, float]]) -> None:
    """``limits`` (xmin, xmax, ymin, ymax, e.g. from around()) fixes the view, so that discs that
    fell off the model do not shrink it to a dot; the figure says how many discs it leaves out."""
    ax.set_aspect("equal")
    ax.autoscale_view()
    if limits is not None:
        ax.set_xlim(*limits[:2])
        ax.set_ylim(*limits[2:])
        left_out = outside(centres, limits)
        if left_out:
            ax.text(0.01, 0.01, f"{left_out} discs outside the view", transform=ax.transAxes, fontsize=7)


def model(out: str, name: str, centres: np.ndarray, radii: Sequence[float], displacement: np.ndarray,
          held: Sequence[bool], joints: Sequence[tuple], set_names: Sequence[str] = (), title: str = "",
          limits: Optional[tuple[float, float, float, float]] = None) -> str:
    """The model a reader must understand: discs at ``centres`` coloured by ``displacement`` (at
    rest, e.g. the last equilibrium), the discs a boundary condition holds (``held``) marked, and
    the joints (((x0, y0), (x1, y1), set) traces, ``toppling.build.joints.joint_traces``) by set."""
    fig, ax = output.figure("x (m)", "y (m)", title, SLOPE_SIZE)
    _discs(ax, fig, centres, radii, displacement, "displacement")
    held = np.asarray(held, dtype=bool)
    if held.any():
        ax.plot(centres[held, 0], centres[held, 1], "s", color="0.2", ms=2, ls="none", label="fixed discs")
    for s in sorted({t[2] for t in joints}):
        segments = [(a, b) for a, b, k in joints if k == s]
        xs = [v for a, b in segments for v in (a[0], b[0], np.nan)]
        ys = [v for a, b in segments for v in (a[1], b[1], np.nan)]
        label = set_names[s] if s < len(set_names) else f"joint set {s + 1}"
        ax.plot(xs, ys, "-", color=SET_COLOURS[s % len(SET_COLOURS)], lw=1.2, label=label)
    _view(ax, centres, limits)
    _legend(ax)
    return output.save_figure(fig, out, name)


MAX_ZONE_LABELS = 30  # one per column up to this many; beyond, where the zone changes (they would overlap)


def zone_labels(zones: Sequence[tuple[float, float, str]]) -> list[tuple[float, float, str]]:
    """The (x, y, zone) labels to draw, columns in order: all, or for many columns the first of
    each run of one zone."""
    if len(zones) <= MAX_ZONE_LABELS:
        return list(zones)
    return [z for k, z in enumerate(zones) if k == 0 or z[2] != zones[k - 1][2]]


def slope(out: str, name: str, centres: np.ndarray, radii: Sequence[float], displacement: np.ndarray,
          cracks: np.ndarray, modes: Sequence[int], planes: Sequence[Plane] = (), toe=(0.0, 0.0),
          title: str = "", limits: Optional[tuple[float, float, float, float]] = None,
          overall: Optional[Plane] = None, zones: Sequence[tuple[float, float, str]] = ()) -> str:
    """Discs at ``centres`` coloured by |displacement| [mm], cracks (x tension, + shear), the
    failure planes (given in the slope frame of upright columns: x - toe_x, y), dashed the
    ``overall`` surface through all the failure points where they split into planes, and each
    column's zone ((x, y, zone): written at (x, y), coloured by zone). ``limits`` as in model()."""
    fig, ax = output.figure("x (m)", "y (m)", title, SLOPE_SIZE)
    _discs(ax, fig, centres, radii, displacement, "displacement")
    cracks, modes = np.asarray(cracks).reshape(-1, 2), np.asarray(modes)
    for mode, marker, colour, label in ((2, "x", "red", "tensile crack"), (3, "+", "blue", "shear crack")):
        sel = modes == mode
        if sel.any():
            ax.plot(cracks[sel, 0], cracks[sel, 1], marker, color=colour, ms=3, ls="none", label=label)
    lines = [(plane, "k-", 2, f"failure surface {k + 1}") for k, plane in enumerate(planes)]
    lines += [(overall, "k--", 1, "overall surface")] if overall is not None else []
    for plane, style, width, what in lines:
        x = np.array(plane.x_range)
        ax.plot(toe[0] + x, toe[1] + plane.intercept + plane.slope * x, style, lw=width,
                label=f"{what}: phi = {plane.phi_deg:.1f} deg")
    for x, y, zone in zone_labels(zones):
        ax.text(x, y, zone.replace("no-movement", "none"), rotation=90, ha="center", va="bottom", fontsize=7,
                color=ZONE_COLOURS.get(zone, "k"))
    _view(ax, centres, limits)
    if len(planes) or len(cracks):
        _legend(ax)
    return output.save_figure(fig, out, name)


def around(centres: np.ndarray, margin: float) -> tuple[float, float, float, float]:
    """The bounding box (xmin, xmax, ymin, ymax) of ``centres`` widened by ``margin`` times
    its larger side on every side."""
    lo, hi = np.min(centres, axis=0), np.max(centres, axis=0)
    pad = margin * float(np.max(hi - lo))
    return float(lo[0] - pad), float(hi[0] + pad), float(lo[1] - pad), float(hi[1] + pad)


def outside(centres: np.ndarray, limits: tuple[float, float, float, float]) -> int:
    """How many ``centres`` lie outside ``limits`` (xmin, xmax, ymin, ymax)."""
    x, y = np.asarray(centres).reshape(-1, 2).T
    inside = (limits[0] <= x) & (x <= limits[1]) & (limits[2] <= y) & (y <= limits[3])
    return int((~inside).sum())


def tilt_history(out: str, energy: Sequence[tuple[float, float, float]], points: MonitoringPoints,
                 failure_tilt: Optional[float]) -> str:
    """Tilt, largest monitoring-point displacement and kinetic energy against simulated time
    (``failure_tilt`` None: the slope stood throughout)."""
    t, tilt, ek = (np.array(c) for c in zip(*energy))
    title = f"failure at {failure_tilt:.1f} deg" if failure_tilt is not None else f"standing at {tilt.max():.1f} deg"
    fig, ax = output.figure("simulated time (s)", "tilt (deg)", f"Tilting, {title}")
    ax.plot(t, tilt, "k-", label="tilt")
    right = ax.twinx()
    right.semilogy(t, np.maximum(ek, 1e-12), "r-", label="kinetic energy (J)")
    biggest = np.max([points.total(label) for label in points.labels], axis=0)
    right.semilogy(points.time, np.maximum(1e3 * biggest, 1e-6), "b-", label="largest column-top displacement (mm)")
    right.legend(loc="upper left", fontsize=7)
    return output.save_figure(fig, out, "tilt_history")


def monitoring(out: str, points: MonitoringPoints, labels: Sequence[str], still: float = 1e-4,
               normal_dydx: Optional[float] = None, turn_deg: float = 0.0, x_into_slope: bool = False) -> str:
    """X, Y, the direction Y/X (the thesis' dY/dX, drawn once a point has moved ``still`` [m]),
    Y against X and total displacement of the labelled points against time (Fig 5-21);
    ``normal_dydx`` draws the direction of the main joints' normal, which a toppling column's top
    passes. X and Y are the scene's turned by ``turn_deg`` clockwise (a table tilted by it made
    level: the world's horizontal and vertical), X pointing into the slope with ``x_into_slope``
    (as the thesis draws a slope, face on the left)."""
    fig, axes = plt.subplots(2, 3, figsize=(14, 7))
    t = np.array(points.time)
    for label in labels:
        x, y = (1e3 * np.array(d) for d in points.displacement(label, turn_deg, x_into_slope))
        axes[0, 0].plot(t, x, label=label)
        axes[0, 1].plot(t, y, label=label)
        axes[0, 2].plot(t, points.direction(label, still, turn_deg, x_into_slope), label=label)
        axes[1, 0].plot(x, y, label=label)
        axes[1, 1].plot(t, np.hypot(x, y), label=label)
    for ax, ylabel in zip(axes.flat, ("X (mm)", "Y (mm)", f"dY/dX = Y/X (once moved {1e3 * still:g} mm)", "Y (mm)",
                                      "total displacement (mm)")):
        ax.set_xlabel("simulated time (s)")
        ax.set_ylabel(ylabel)
        ax.grid(True, alpha=0.3)
    axes[1, 0].set_xlabel("X (mm)")
    axes[1, 2].axis("off")
    if normal_dydx is not None:
        normal = axes[0, 2].axhline(normal_dydx, color="r", ls="--", lw=1, label="normal to the main joints")
        axes[0, 2].legend(handles=[normal], fontsize=7, loc="lower left")
    axes[0, 2].set_ylim(-5, 5)
    axes[0, 0].legend(fontsize=7)
    return output.save_figure(fig, out, "monitoring_points")
