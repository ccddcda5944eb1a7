"""Statistics over the runs of one model drawn with different seeds (their summaries): mean ± standard deviation,
a mean against a target and a difference of two means, each judged by two standard errors
against a tolerance (yes, no or undecided). Pure Python."""
from __future__ import annotations

import statistics


def fmt(value, digits=1):
    if value is None:
        return "-"
    if isinstance(value, list):
        return ", ".join(fmt(v, digits) for v in value) or "-"
    return f"{value:.{digits}f}"


def stats_text(values: list[float]) -> str:
    if len(values) < 2:
        return fmt(values[0]) if values else "-"
    return f"{statistics.mean(values):.1f} ± {statistics.stdev(values):.1f}"


def within(d: float, se: float, tolerance: float) -> str:
    """Whether a difference ``d`` with standard error ``se`` is within ``tolerance``: yes if it
    is by two standard errors, no if it is outside by two, undecided otherwise."""
    return "yes" if abs(d) + 2 * se <= tolerance else "no" if abs(d) - 2 * se > tolerance else "undecided"


def difference_from(values: list[float], target: float) -> tuple[float, float]:
    """The mean of two or more ``values`` minus ``target``, and the mean's standard error."""
    return statistics.mean(values) - target, statistics.stdev(values) / len(values) ** 0.5


def se_of_difference(fine: list[float], coarse: list[float]) -> float:
    """The standard error of the difference of the means of two or more ``fine`` and ``coarse``."""
    return (statistics.variance(fine) / len(fine) + statistics.variance(coarse) / len(coarse)) ** 0.5


def mean_difference(fine: list[float], coarse: list[float], tolerance: float) -> tuple[str, str]:
    """The difference of the means of ``fine`` and ``coarse`` with its standard error, and
    whether it is within ``tolerance``: yes if it is by two standard errors, no if it is
    outside by two, undecided otherwise (or with fewer than two values on a side)."""
    if not fine or not coarse:
        return "-", "-"
    d = statistics.mean(fine) - statistics.mean(coarse)
    if min(len(fine), len(coarse)) < 2:
        return f"{d:+.1f}", f"undecided ({len(fine)} vs {len(coarse)} seeds)"
    se = se_of_difference(fine, coarse)
    return f"{d:+.1f} ± {se:.1f}", within(d, se, tolerance)


def inside_band(tilts: list[float], target: float, tolerance: float) -> int:
    """How many ``tilts`` are within ``tolerance`` of ``target``."""
    return sum(abs(t - target) <= tolerance for t in tilts)


def mean_against(values: list[float], target: float, tolerance: float) -> str:
    """The mean of two or more ``values`` minus ``target``, its standard error, and whether the
    mean is within ``tolerance`` of the target (``within``); undecided from two values,
    whose standard deviation says little (two tilts in the same 2° stage give 0)."""
    d, se = difference_from(values, target)
    verdict = within(d, se, tolerance) if len(values) > 2 else "undecided (2 draws)"
    return f"{d:+.1f} ± {se:.1f}: {verdict}"


def first_stage_failure(s: dict) -> bool:
    """Whether a run failed in its first stage: its failure tilt is only an upper bound."""
    return s["failure_tilt_deg"] is not None and s.get("failed_in_first_stage", False)


def failed_seeds(group: list[dict]) -> list[dict]:
    """The runs of ``group`` with a failure tilt that is not only an upper bound."""
    return [s for s in group if s["failure_tilt_deg"] is not None and not first_stage_failure(s)]
