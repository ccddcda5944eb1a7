"""Issue 4's verdicts on the ideal model's failure tilt at 95 kPa, recomputed from the record of
every seed in docs/tilting_table.md (the table after "Every seed at 95 kPa"), so that they can
be checked on a machine that has none of the runs.

    python3 calibration/tilting_table/seed_record.py [docs/tilting_table.md]

For each packing size (a column of the record): seeds, mean ± standard deviation, median, seeds
within 3 deg of the thesis' 35 deg, the mean minus 35 with its standard error and verdict
(collect_tilting_table.mean_against), and the margin |mean - 35| + 2 standard errors that the
verdict compares with 3 deg. Then the size check: each finer column's mean minus the first
column's, with the verdict of collect_tilting_table.mean_difference; the chance that the seeds
in hand read "yes" if the true difference were 0; and the seeds per size at which "yes" comes
with a chance of YES_CHANCE if the true difference is 0, and if it is the measured one, at the
spreads measured so far ("none" when the measured difference alone reaches the tolerance).
A "yes" needs |difference| + 2 standard errors within the tolerance, so at the seeds where two
standard errors just fill it (what this script printed until 2026-12-04) even a true difference
of 0 reads "yes" with a chance of 0: a plan of runs needs that chance, not that edge.
Last, the same difference paired by seed (the rows with a tilt in both columns): the pairs, the
correlation of the two sizes' tilts and the mean of the per-seed differences with its standard
error. It is printed beside the size check, not in its place: the check was set on the means of
all seeds per size before the record showed whether a seed's two packings fail alike.

A seed stopped before it failed (its run lost with a machine's `results/`) has a cell "≥ 40 (333;
...)": it stood at 38 deg, so its failure tilt is at least 40. Such seeds are left out of the
verdicts, and since the seeds that stand longest are the likeliest to be stopped, leaving them out
pulls a mean down; so the same rows are printed again with them counted at their lower bounds.
"""
import os
import re
import statistics
import sys
from typing import Iterable

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import collect_tilting_table as collect  # noqa: E402

RECORD_HEADING = "**Every seed at 95 kPa.**"
THESIS_TILT_DEG = 35.0  # thesis Table 5-4, the ideal model
TILT_CELL = re.compile(r"\s*(\d+(?:\.\d+)?)\s*\(")  # "38 (190)": failure tilt (table line)
BOUND_CELL = re.compile(r"\s*≥\s*(\d+(?:\.\d+)?)\s*\(")  # "≥ 40 (333; ...)": a seed stopped unfailed
YES_CHANCE = 0.8  # the chance of a "yes" that a plan of runs is sized for (the usual power, 80 %)


def record_columns(lines: Iterable[str]) -> tuple[list[str], list[list[str]]]:
    """The record's packing sizes (its columns' headers up to their colons) and its rows' cells."""
    header, rows = collect.record_table(lines, RECORD_HEADING)
    return [text.split(":")[0].strip() for text in header[1:]], rows


def read_record(lines: Iterable[str], cell: re.Pattern = TILT_CELL) -> dict[str, list[float]]:
    """The numbers that ``cell`` matches, by packing size (the column's header up to its colon),
    in the first Markdown table after RECORD_HEADING: failure tilts by default, lower bounds with
    BOUND_CELL; a cell that does not match (a seed not run, "–") is left out."""
    sizes, rows = record_columns(lines)
    tilts: dict[str, list[float]] = {size: [] for size in sizes}
    for row in rows:
        for size, text in zip(sizes, row[1:]):
            match = cell.match(text)
            if match:
                tilts[size].append(float(match.group(1)))
    return tilts


def with_bounds(tilts: dict[str, list[float]], bounds: dict[str, list[float]]) -> dict[str, list[float]]:
    """Each size's failure tilts followed by its unfinished seeds' lower bounds."""
    return {size: values + bounds.get(size, []) for size, values in tilts.items()}


def margin(tilts: list[float]) -> float:
    """|mean - 35| + 2 standard errors: at most 3 deg is "met" (collect_tilting_table.within)."""
    se = statistics.stdev(tilts) / len(tilts) ** 0.5
    return abs(statistics.mean(tilts) - THESIS_TILT_DEG) + 2 * se


def chance_of_yes(difference: float, se: float, tolerance: float = collect.SIZE_TOLERANCE_DEG) -> float:
    """The chance that a measured difference, normal about a true ``difference`` with standard error
    ``se``, reads "yes" (collect.within): |measured| + 2 se within ``tolerance``."""
    room = tolerance - 2 * se
    if room <= 0:
        return 0.0
    measured = statistics.NormalDist(difference, se)
    return measured.cdf(room) - measured.cdf(-room)


def seeds_for_yes(fine: list[float], coarse: list[float], difference: float = 0.0) -> int | None:
    """The fewest seeds per size at which a true ``difference`` of the means reads "yes" with a
    chance of YES_CHANCE at the two sizes' spreads; None if |difference| alone reaches the
    tolerance, where no number of seeds gives that chance."""
    if abs(difference) >= collect.SIZE_TOLERANCE_DEG:
        return None
    spread = statistics.variance(fine) + statistics.variance(coarse)
    n = 2
    while chance_of_yes(difference, (spread / n) ** 0.5) < YES_CHANCE:
        n += 1
    return n


def read_pairs(lines: Iterable[str]) -> dict[str, list[tuple[float, float]]]:
    """(first column's tilt, this column's tilt) for each seed failed at both, by finer size."""
    sizes, rows = record_columns(lines)
    pairs: dict[str, list[tuple[float, float]]] = {size: [] for size in sizes[1:]}
    for row in rows:
        matches = [TILT_CELL.match(text) for text in row[1:]]
        if not matches[0]:
            continue
        for size, match in zip(sizes[1:], matches[1:]):
            if match:
                pairs[size].append((float(matches[0].group(1)), float(match.group(1))))
    return pairs


def paired_row(size: str, coarse_size: str, pairs: list[tuple[float, float]]) -> str:
    """The Markdown row of the difference paired by seed: pairs, correlation, mean ± standard error."""
    coarse, fine = zip(*pairs)
    differences = [b - a for a, b in pairs]
    se = statistics.stdev(differences) / len(differences) ** 0.5
    return (f"| {size} − {coarse_size} | {len(pairs)} | {statistics.correlation(coarse, fine):.2f} | "
            f"{statistics.mean(differences):+.2f} ± {se:.2f} |")


def paired_report(lines: list[str]) -> list[str]:
    """The Markdown rows of the difference paired by seed, one per finer size with two pairs or more."""
    coarse_size = record_columns(lines)[0][0]
    rows = ["| paired by seed | pairs | correlation | mean of fine − coarse ± standard error (°) |", "|---|---|---|---|"]
    return rows + [paired_row(size, coarse_size, pairs) for size, pairs in read_pairs(lines).items() if len(pairs) >= 2]


def report(tilts: dict[str, list[float]]) -> list[str]:
    """The Markdown rows of the verdicts and the size check (module docstring)."""
    rows = [f"| packing | seeds | failure tilt (°) | median | within 3° of {THESIS_TILT_DEG:g}° | "
            f"{collect.MEAN_AGAINST_HEADER} | margin (°) |", "|---|---|---|---|---|---|---|"]
    for size, values in tilts.items():
        inside = collect.inside_band(values, THESIS_TILT_DEG)
        rows.append(f"| {size} | {len(values)} | {collect.stats_text(values)} | {statistics.median(values):g} | "
                    f"{inside} | {collect.mean_against(values, THESIS_TILT_DEG)} | {margin(values):.2f} |")
    coarse_size, coarse = next(iter(tilts.items()))
    rows += ["", "| size check | difference of the means ± standard error (°) | within 2°? | "
             "chance of a yes with these seeds at a difference of 0 | "
             f"seeds per size for a yes with a chance of {YES_CHANCE:.0%} at a difference of 0 | at the measured difference |",
             "|---|---|---|---|---|---|"]
    for size, fine in list(tilts.items())[1:]:
        difference, verdict = collect.mean_difference(fine, coarse)
        chance = chance_of_yes(0.0, collect.se_of_difference(fine, coarse))
        measured = seeds_for_yes(fine, coarse, statistics.mean(fine) - statistics.mean(coarse))
        rows.append(f"| {size} − {coarse_size} | {difference} | {verdict} | {chance:.0%} | "
                    f"{seeds_for_yes(fine, coarse)} | {'none' if measured is None else measured} |")
    return rows


def main(path: str) -> None:
    with open(path) as f:
        lines = f.read().splitlines()
    tilts, bounds = read_record(lines), read_record(lines, BOUND_CELL)
    print("\n".join(report(tilts)))
    print("\n" + "\n".join(paired_report(lines)))
    unfinished = ", ".join(f"{size} {len(values)}" for size, values in bounds.items() if values)
    if unfinished:
        print(f"\nWith the seeds stopped before they failed ({unfinished}) at their lower bounds:\n")
        print("\n".join(report(with_bounds(tilts, bounds))))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "docs", "tilting_table.md"))
