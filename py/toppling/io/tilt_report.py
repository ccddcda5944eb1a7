"""What a finished tilting-table run leaves: ``summary.json``, the figures and its last console
line, for a slope that failed (its failure surface, zones, S/H and T/H, after the post-failure run
and at the failure's onset), stood up to max_tilt, or was stopped at max_wall_time."""
from __future__ import annotations

import math

import numpy as np
from yade import O

from toppling.analyse import failure
from toppling.build import boundary, engines, jcfpm, joints
from toppling.io import output, plots
from toppling.run.tilt_run import TiltRun, arrested_text, ramp_warning

# The records are in the table's frame, in which the columns stand upright: the main joints'
# normal runs along the table, Y/X = 0, and a column top toppling outwards falls below it.
TABLE_NORMAL_DYDX = 0.0


def report(run: TiltRun, out: str, thesis: dict, name: str) -> None:
    """Write the run's summary and figures into ``out`` and print its result beside ``thesis``
    (``failure_tilt_deg``, ``phi_deg``); ``name`` (the arrangement) titles them."""
    if run.state.get("stopped"):
        report_stopped(run, out, thesis)
        return
    if warning := ramp_warning(run.state.get("breaks_before_stages") or {}):  # again beside the result it qualifies
        print(warning)
    if run.failure_tilt is None:
        report_stable(run, out, thesis, name)
    else:
        report_failure(run, out, thesis, name)
    jcfpm.keep_cracks(out)  # a stopped run leaves it where JCFpm goes on writing when it resumes


def report_stopped(run: TiltRun, out: str, thesis: dict) -> None:
    """Stopped at max_wall_time: the summary says why and how far the run came, no failure yet."""
    record = dict(thesis=thesis, **run.record())
    tilts = [stage["tilt"] for stage in run.state["stages"] if stage["outcome"] == "equilibrium"]
    output.write_summary(out, run.state["inputs"], failed=None, failure_tilt_deg=None,
                         stable_up_to_deg=max(tilts, default=None), phi_deg=[], **record)
    print(f"stopped before the run's end: {record['stopped']}")


def report_stable(run: TiltRun, out: str, thesis: dict, name: str) -> None:
    """Stable throughout: the summary says so (a sweep goes on) and how far each column top
    moved, which shows what holds the slope; a higher max_tilt continues the run."""
    points, state = run.points, run.state
    tops, record = {label: 1e3 * points.total(label)[-1] for label in points.labels}, dict(thesis=thesis, **run.record())
    output.write_summary(out, state["inputs"], failed=False, failure_tilt_deg=None, stable_up_to_deg=state["stages"][-1]["tilt"],
                         phi_deg=[], s_over_h=None, t_over_h=None, top_displacement_mm=tops, **record)
    plot_model(run, out, name)
    plots.tilt_history(out, state["energy"], points, None)
    plot_monitoring(run, out, thesis)
    arrested = arrested_text(record["arrested_failures"])
    print(f"no failure up to max_tilt = {run.protocol.max_tilt} deg{arrested}: run again with a higher max_tilt; "
          "column tops moved " + ", ".join(f"{label} {mm:.2f}" for label, mm in tops.items()) + " mm")


def plot_monitoring(run: TiltRun, out: str, thesis: dict) -> None:
    """The monitoring points' records (Fig 5-21): of the tilting table, every other column top in
    the table's frame; of a slope settled at a tilt (its world), the thesis' points
    (``thesis["monitoring_points"]``) in the world's frame, drawn as the thesis draws a slope."""
    points, tilt = run.points, run.protocol.settle_tilt
    if tilt == 0:
        plots.monitoring(out, points, points.labels[::2], normal_dydx=TABLE_NORMAL_DYDX)
        return
    labels = [label for label in thesis.get("monitoring_points", points.labels[::2]) if label in points.labels]
    plots.monitoring(out, points, labels, normal_dydx=math.tan(math.radians(tilt)), turn_deg=tilt, x_into_slope=True)


def report_failure(run: TiltRun, out: str, thesis: dict, name: str) -> None:
    """The failure's analysis (surfaces, zones, S/H, T/H), summary and figures."""
    state, tilt = run.state, run.failure_tilt
    result, onset = run.analyse(tilt), run.analyse(tilt, state["onset"])
    summary = dict(
        failed=True, failure_tilt_deg=tilt,
        failed_in_first_stage=len(state["stages"]) == 1,  # then failure_tilt_deg is only an upper bound
        **failure.surface_angles(result),
        planes=len(result["planes"]), two_planes_p=result["split_p"],
        s_over_h=result["s_over_h"], t_over_h=result["t_over_h"],
        zones={failure.column_label(k + 1): z for k, z in enumerate(result["zones"])},
        stable_zone_columns=[k + 1 for k, z in enumerate(result["zones"]) if z == "stable"],
        failure_points=result["failure_points"], slope_height=result["height"], thesis=thesis,
        onset={**failure.surface_angles(onset), "s_over_h": onset["s_over_h"], "t_over_h": onset["t_over_h"],
               "zones": {failure.column_label(k + 1): z for k, z in enumerate(onset["zones"])}},
        **run.record())
    output.write_summary(out, state["inputs"], **summary)
    phi_text = f"phi = {failure.phi_text(summary)} deg" if summary["phi_deg"] else "no failure surface found"
    plot_failure(run, out, name, onset, result, thesis)
    if summary["failed_in_first_stage"] and run.protocol.start_tilt > run.protocol.settle_tilt:  # else one tilt by design
        print(f"WARNING: the first stage ({run.protocol.start_tilt} deg) failed: the failure tilt is at most that; "
              "rerun with a lower start_tilt")
    distances = ", ".join(f"{label} {summary[key]:.2f}" if summary[key] is not None else f"{label} -"
                          for label, key in (("S/H", "s_over_h"), ("T/H", "t_over_h")))
    print(f"{name}: failure tilt {tilt:.1f} deg{beside(thesis.get('failure_tilt_deg'))}"
          f"{arrested_text(summary['arrested_failures'])}, {phi_text}{beside(thesis.get('phi_deg'))}, {distances}, "
          f"{summary['tensile_breaks']} tensile / {summary['shear_breaks']} shear breaks, {len(run.ids)} discs, "
          f"{summary['wall_time']:.0f} s")


JOINT_SETS = ("main joints", "cross (base) joints")  # in the order the tilting-table model installs them


def radii(run: TiltRun) -> list[float]:
    return [O.bodies[i].shape.radius for i in run.ids]


def view(run: TiltRun) -> tuple[float, float, float, float]:
    """The picture's limits: the columns and a margin (discs fallen off the table stay out of it)."""
    return plots.around(np.array(run.layout.section()), 0.15)


def plot_model(run: TiltRun, out: str, name: str) -> None:
    """``slope_before.png``: the model at its last equilibrium: joints by set, the fixed discs,
    and how far the discs had moved there since the model was built."""
    built = np.array(run.state["built"])
    at_rest = np.array(run.state["reference"])
    stood = [s["tilt"] for s in run.state["stages"] if s["outcome"] == "equilibrium"]
    when = f"{stood[-1]:.0f} deg" if stood else "the level table"
    plots.model(out, "slope_before", at_rest, radii(run), at_rest - built, [boundary.is_held(O.bodies[i]) for i in run.ids],
                joints.joint_traces(dict(zip(run.ids, map(tuple, built)))), JOINT_SETS, limits=view(run),
                title=f"{name} arrangement at the last equilibrium ({when})")


def zone_marks(run: TiltRun, zones: list[str]) -> list[tuple[float, float, str]]:
    """Where each column's zone is written: in a row above the columns, over its centre."""
    row = 1.05 * max(run.layout.heights)
    return [(run.layout.top_centre(k + 1)[0], row, zone) for k, zone in enumerate(zones)]


def plot_slope(run: TiltRun, out: str, name: str, result: dict, breaks: int, title: str) -> None:
    """The slope of ``result`` (TiltRun.analyse): displacement since the last equilibrium, the
    first ``breaks`` cracks by mode, the fitted surface(s) and the zones by column."""
    law = engines.break_record()
    cracks = np.array([tuple(p)[:2] for p in law.breakPosition][:breaks]).reshape(-1, 2)
    plots.slope(out, name, result["now"], radii(run), result["disp"], cracks, list(law.breakMode)[:breaks],
                result["planes"], toe=(run.layout.toe_x, 0.0), limits=view(run), title=title,
                overall=result["overall"] if len(result["planes"]) > 1 else None,
                zones=zone_marks(run, result["zones"]))


def beside(thesis_value) -> str:
    """The thesis' figure in brackets, or nothing where the thesis gives none (a slope judged at
    its own tilt has no failure tilt to compare)."""
    return "" if thesis_value is None or thesis_value == [] else f" (thesis {thesis_value})"


def plot_failure(run: TiltRun, out: str, name: str, onset: dict, after: dict, thesis: dict) -> None:
    """The model, the failure at its onset (the failing stage's end, as the thesis' Fig 5-8) and
    after the post-failure run, the tilt history and the monitoring points."""
    tilt, points = run.failure_tilt, run.points
    plot_model(run, out, name)
    for picture, result, breaks, when in (("slope_failure", onset, run.state["onset"]["breaks"], "onset of failure"),
                                          ("slope_after", after, None, "after the post-failure run")):
        phi = failure.phi_text(failure.surface_angles(result)) if result["planes"] else "-"
        plot_slope(run, out, picture, result, breaks, f"{name}: {when} at {tilt:.1f} deg, phi = {phi} deg")
    plots.tilt_history(out, run.state["energy"], points, tilt)
    plot_monitoring(run, out, thesis)
