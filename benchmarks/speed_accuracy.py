"""Speed against accuracy: what a run costs at each packing size, and how far its answer lies
from the finest packing's (docs/performance.md).

The tilting table's ideal model and the equivalent slope's base model, each at column width /
Rmax from 5 to 25 (the radii ratio of the thesis' packing: 2.5 for the tilting table, §5.2.3;
the base model's 2.33), plus the tilting table's calibrated default (R 1-4 mm), 5 packing seeds
each; every other parameter the example's default.

    source scripts/env.sh; /usr/bin/python3 benchmarks/speed_accuracy.py tables   # the two batch tables
    ./toppling-sweep benchmarks/speed_accuracy_tilting_table.table examples/tilting_table/run.py
    ./toppling-sweep benchmarks/speed_accuracy_equivalent_slope.table examples/equivalent_slope/run.py
    source scripts/env.sh; /usr/bin/python3 benchmarks/speed_accuracy.py report   # Markdown, CSV, charts
    source scripts/env.sh; /usr/bin/python3 benchmarks/speed_accuracy.py missing  # each table's lines not run yet
The report first adds the finished runs to the record (benchmarks/records/speed_accuracy_<model>.csv,
kept in git: a new machine starts from it), then reads every run from there; it writes
results/speed_accuracy/<model>.csv and .png.
"""
import csv
import os
import statistics
import sys

from examples import params
from toppling.io import output, records

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = "results/speed_accuracy"
SEEDS = (1, 2, 3, 4, 5)
# model: (column width [m], Rmax / Rmin, width / Rmax of the sizes, the thesis' size, extra sizes (Rmin, Rmax))
MODELS = {
    "tilting_table": (params.TILTING_TABLE_OUTLINE["width"], params.PACKING_R_RATIO, (5, 9, 14, 20, 25), 20,
                      [(params.TILTING_TABLE_IDEAL["rmin"], params.TILTING_TABLE_IDEAL["rmax"])]),
    "equivalent_slope": (params.EQUIVALENT_SLOPE_SHAPE["spacing"],
                         params.EQUIVALENT_SLOPE["rmax"] / params.EQUIVALENT_SLOPE["rmin"],
                         (5, 9, params.EQUIVALENT_SLOPE_SHAPE["spacing"] / params.EQUIVALENT_SLOPE["rmax"], 20, 25),
                         params.EQUIVALENT_SLOPE_SHAPE["spacing"] / params.EQUIVALENT_SLOPE["rmax"], []),
}
# the answers compared, by model: summary key, label
ANSWERS = {"tilting_table": [("failure_tilt_deg", "failure tilt (°)"), ("phi_overall_deg", "φ overall (°)"),
                             ("s_over_h", "S/H")],
           "equivalent_slope": [("failed", "fails (fraction of seeds)"), ("phi_overall_deg", "φ overall (°)"),
                                ("s_over_h", "S/H"), ("t_over_h", "T/H")]}


def sizes(model: str) -> list[tuple[float, float]]:
    """(rmin, rmax) [m] of the model's packings, coarse to fine."""
    width, ratio, per_width, _, extra = MODELS[model]
    found = [(round(width / w / ratio, 6), round(width / w, 6)) for w in per_width] + extra
    return sorted(found, key=lambda r: -r[1])


def write_tables() -> None:
    """One line per size and seed, size by size from the coarsest (a sweep stopped part way has the cheap sizes)."""
    for model in MODELS:
        rows = [["description", "seed", "rmin", "rmax", "out"]]
        for rmin, rmax in sizes(model):
            for seed in SEEDS:
                name = f"r{1e3 * rmin:g}-{1e3 * rmax:g}_s{seed}"
                rows.append([name, str(seed), repr(rmin), repr(rmax), f"'{RESULTS}/{model}/{name}'"])
        width = [max(len(r[k]) for r in rows) for k in range(len(rows[0]))]
        with open(f"{HERE}/speed_accuracy_{model}.table", "w") as f:
            f.write(f"# Written by benchmarks/speed_accuracy.py tables; run with\n#   ./toppling-sweep "
                    f"benchmarks/speed_accuracy_{model}.table examples/{model}/run.py\n")
            for row in rows:
                f.write(" ".join(c.ljust(w) for c, w in zip(row, width)).rstrip() + "\n")


def value(summary: dict, key: str):
    """A summary's figure as a record holds it: flags as 0 or 1 (``failed`` absent: 0)."""
    v = bool(summary.get(key)) if key == "failed" else summary.get(key)
    return float(v) if isinstance(v, bool) else v


COST = ("rmin", "rmax", "seed", "discs", "steps", "wall_time", "failed_in_first_stage")


def record(model: str) -> dict[str, dict]:
    """The model's record with the finished runs in results/ added: every run, by name."""
    def row(name: str, s: dict) -> dict:
        return {"run": name, **{k: s["inputs"][k] for k in ("rmin", "rmax", "seed")},
                **{k: value(s, k) for k in COST[3:]}, **{k: value(s, k) for k, _ in ANSWERS[model]},
                "commit": records.commit(s)}
    numbers = COST + tuple(k for k, _ in ANSWERS[model])
    return records.update(f"{HERE}/records/speed_accuracy_{model}.csv", f"{RESULTS}/{model}", row, numbers)


def by_size(model: str) -> list[dict]:
    """Per size (coarse to fine): the runs' cost and each answer's values."""
    runs = record(model)
    found = []
    for rmin, rmax in sizes(model):
        mine = [s for s in runs.values() if (s["rmin"], s["rmax"]) == (rmin, rmax)]
        if not mine:
            continue
        row = {"rmin": rmin, "rmax": rmax, "width_over_rmax": MODELS[model][0] / rmax, "runs": len(mine),
               "discs": statistics.mean(s["discs"] for s in mine), "steps": statistics.mean(s["steps"] for s in mine),
               "wall_time": statistics.mean(s["wall_time"] for s in mine),
               "first_stage": sum(bool(s.get("failed_in_first_stage")) for s in mine)}  # a failure tilt at most that
        for key, _ in ANSWERS[model]:
            row[key] = [s[key] for s in mine if s[key] is not None]
        found.append(row)
    return found


def spread(values: list[float]) -> tuple[float, float]:
    return statistics.mean(values), statistics.stdev(values) if len(values) > 1 else 0.0


def report(model: str) -> None:
    rows = by_size(model)
    if not rows:
        print(f"{model}: no runs in {RESULTS}/{model}")
        return
    finest = rows[-1]
    answers = ANSWERS[model]
    print(f"\n{model} (finest: R {1e3 * finest['rmin']:g}-{1e3 * finest['rmax']:g} mm; shift = mean − finest's mean)\n")
    staged = any(key == "failure_tilt_deg" for key, _ in answers)  # a slope run at one tilt has one stage
    runs = "runs (failed in the first stage)" if staged else "runs"
    print(f"| R (mm) | width / Rmax | {runs} | discs | steps | wall (s) | " + " | ".join(f"{label}: mean ± sd, shift"
                                                                            for _, label in answers) + " |")
    print("|---|---|---|---|---|---|" + "---|" * len(answers))
    table = []
    for row in rows:
        cells = []
        for key, _ in answers:
            if row[key] and finest[key]:
                (m, sd), (m0, _) = spread(row[key]), spread(finest[key])
                cells.append(f"{m:.2f} ± {sd:.2f}, {m - m0:+.2f}")
                row[f"{key}_mean"], row[f"{key}_sd"], row[f"{key}_shift"] = m, sd, m - m0
            else:
                cells.append("-")
        first = f" ({row['first_stage']})" if staged else ""
        print(f"| {1e3 * row['rmin']:g}–{1e3 * row['rmax']:g} | {row['width_over_rmax']:.1f} | {row['runs']}{first} | "
              f"{row['discs']:.0f} | {row['steps']:.0f} | {row['wall_time']:.0f} | " + " | ".join(cells) + " |")
        table.append({k: v for k, v in row.items() if not isinstance(v, list)})
    print(recommended(rows, answers))
    with open(f"{output.output_dir(RESULTS)}/{model}.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=sorted({k for r in table for k in r}))
        w.writeheader()
        w.writerows(table)
    chart(model, rows)


def recommended(rows: list[dict], answers: list[tuple[str, str]]) -> str:
    """The cheapest size whose every answer's mean lies within the finest's seed sd of the finest's
    mean: coarser than that, the answer moves by more than the packing's own scatter."""
    finest = rows[-1]
    keys = [key for key, _ in answers if f"{key}_shift" in finest]
    for row in sorted(rows, key=lambda r: r["wall_time"]):
        if all(f"{key}_shift" in row and abs(row[f"{key}_shift"]) <= finest[f"{key}_sd"] for key in keys):
            which = "the finest itself" if row is finest else f"{row['wall_time'] / finest['wall_time']:.2f} of its wall time"
            return (f"recommended: width / Rmax {row['width_over_rmax']:.1f} (R {1e3 * row['rmin']:g}–{1e3 * row['rmax']:g} "
                    f"mm), {which}: every answer within the finest's seed sd of its mean")
    return "recommended: none"


def chart(model: str, rows: list[dict]) -> None:
    """Cost (x, log) against each answer's shift from the finest (y), the seed spread as a band."""
    answers = ANSWERS[model]
    fig, axes = output.plt.subplots(1, len(answers), figsize=(4 * len(answers), 3.6))
    thesis = MODELS[model][3]
    for ax, (key, label) in zip(axes, answers):
        shown = [r for r in rows if f"{key}_shift" in r]
        x = [r["wall_time"] for r in shown]
        y = [r[f"{key}_shift"] for r in shown]
        sd = [r[f"{key}_sd"] for r in shown]
        ax.fill_between(x, [a - b for a, b in zip(y, sd)], [a + b for a, b in zip(y, sd)], alpha=0.25,
                        label="± seed sd")
        ax.plot(x, y, "o-", label="mean − finest's")
        for r in shown:
            ax.annotate(f"{r['width_over_rmax']:.0f}", (r["wall_time"], r[f"{key}_shift"]), fontsize=7)
            if abs(r["width_over_rmax"] - thesis) < 0.5:
                ax.plot(r["wall_time"], r[f"{key}_shift"], "r*", markersize=12, label="thesis' resolution")
        ax.axhline(0, color="grey", lw=0.5)
        ax.set(xscale="log", xlabel="wall time per run (s, one core)", ylabel=f"shift of {label}")
    axes[0].legend(fontsize=7)
    fig.suptitle(f"{model}: cost against answer (labels: column width / Rmax)")
    output.save_figure(fig, RESULTS, model)


if __name__ == "__main__":
    if sys.argv[1:] == ["tables"]:
        write_tables()
    elif sys.argv[1:] == ["missing"]:
        for name in MODELS:
            print(f"{name}: --lines {records.missing(f'{HERE}/speed_accuracy_{name}.table', record(name)) or '(none)'}")
    else:
        for name in MODELS:
            report(name)
