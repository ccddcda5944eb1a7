"""What a finished tilting-table run leaves: ``summary.json``, the figures and its last console
line, for a slope that failed (its failure surface, zones, S/H and T/H) or stood up to max_tilt."""
from __future__ import annotations

import numpy as np
from yade import O

from toppling.analyse import failure
from toppling.build import engines
from toppling.io import output, plots
from toppling.run.tilt_run import TiltRun, arrested_text, ramp_warning

# The records are in the table's frame, in which the columns stand upright: the main joints'
# normal runs along the table, Y/X = 0, and a column top toppling outwards falls below it.
TABLE_NORMAL_DYDX = 0.0


def report(run: TiltRun, out: str, thesis: dict, name: str) -> None:
    """Write the run's summary and figures into ``out`` and print its result beside ``thesis``
    (``failure_tilt_deg``, ``phi_deg``); ``name`` (the arrangement) titles them."""
    if warning := ramp_warning(run.state.get("breaks_before_stages") or {}):  # again beside the result it qualifies
        print(warning)
    if run.failure_tilt is None:
        report_stable(run, out, thesis)
    else:
        report_failure(run, out, thesis, name)


def report_stable(run: TiltRun, out: str, thesis: dict) -> None:
    """Stable throughout: the summary says so (a sweep goes on) and how far each column top
    moved, which shows what holds the slope; a higher max_tilt continues the run."""
    points, state = run.points, run.state
    tops, record = {label: 1e3 * points.total(label)[-1] for label in points.labels}, dict(thesis=thesis, **run.record())
    output.write_summary(out, state["inputs"], failure_tilt_deg=None, stable_up_to_deg=state["stages"][-1]["tilt"],
                         phi_deg=[], s_over_h=None, t_over_h=None, top_displacement_mm=tops, **record)
    plots.tilt_history(out, state["energy"], points, None)
    plots.monitoring(out, points, points.labels[::2], normal_dydx=TABLE_NORMAL_DYDX)
    arrested = arrested_text(record["arrested_failures"])
    print(f"no failure up to max_tilt = {run.protocol.max_tilt} deg{arrested}: run again with a higher max_tilt; "
          "column tops moved " + ", ".join(f"{label} {mm:.2f}" for label, mm in tops.items()) + " mm")


def report_failure(run: TiltRun, out: str, thesis: dict, name: str) -> None:
    """The failure's analysis (surfaces, zones, S/H, T/H), summary and figures."""
    state, tilt = run.state, run.failure_tilt
    result = run.analyse(tilt)
    summary = dict(
        failure_tilt_deg=tilt,
        failed_in_first_stage=len(state["stages"]) == 1,  # then failure_tilt_deg is only an upper bound
        **failure.surface_angles(result),
        planes=len(result["planes"]), two_planes_p=result["split_p"],
        s_over_h=result["s_over_h"], t_over_h=result["t_over_h"],
        zones={failure.column_label(k + 1): z for k, z in enumerate(result["zones"])},
        failure_points=result["failure_points"], slope_height=result["height"], thesis=thesis, **run.record())
    output.write_summary(out, state["inputs"], **summary)
    phi_text = f"phi = {failure.phi_text(summary)} deg" if summary["phi_deg"] else "no failure surface found"
    plot_failure(run, out, result, f"{name}: failed at {tilt:.1f} deg, {phi_text}", name)
    if summary["failed_in_first_stage"]:
        print(f"WARNING: the first stage ({run.protocol.start_tilt} deg) failed: the failure tilt is at most that; "
              "rerun with a lower start_tilt")
    distances = ", ".join(f"{label} {summary[key]:.2f}" if summary[key] is not None else f"{label} -"
                          for label, key in (("S/H", "s_over_h"), ("T/H", "t_over_h")))
    print(f"{name}: failure tilt {tilt:.1f} deg (thesis {thesis['failure_tilt_deg']})"
          f"{arrested_text(summary['arrested_failures'])}, {phi_text} (thesis {thesis['phi_deg']}), {distances}, "
          f"{summary['tensile_breaks']} tensile / {summary['shear_breaks']} shear breaks, {len(run.ids)} discs, "
          f"{summary['wall_time']:.0f} s")


def plot_failure(run: TiltRun, out: str, result: dict, title: str, name: str) -> None:
    """The slope at the last equilibrium and after the failure (displacement, cracks by mode,
    fitted surfaces), the tilt history and the monitoring points."""
    law, points = engines.bond_law(), run.points
    radii = [O.bodies[i].shape.radius for i in run.ids]
    view = plots.around(np.array(run.layout.section()), 0.15)  # discs fallen off the table stay out of it
    cracks = np.array([tuple(p)[:2] for p in law.breakPosition]).reshape(-1, 2)
    plots.slope(out, "slope_before", np.array(run.state["reference"]), radii, np.zeros((len(run.ids), 2)), [], [],
                limits=view, title=f"{name} arrangement at the last equilibrium")
    plots.slope(out, "slope_after", result["now"], radii, result["disp"], cracks, list(law.breakMode),
                result["planes"], toe=(run.layout.toe_x, 0.0), limits=view, title=title,
                overall=result["overall"] if len(result["planes"]) > 1 else None)
    plots.tilt_history(out, run.state["energy"], points, run.failure_tilt)
    plots.monitoring(out, points, points.labels[::2], normal_dydx=TABLE_NORMAL_DYDX)
