"""Accuracy against cost of the tilting-table model: failure tilt of every draw (packing seed,
and for the random arrangement layout seed) against the wall time of its run, one colour per
packing size, the mean ± sd over the draws at each size's mean wall time and the thesis' target
± 3 deg shaded.

    python3 calibration/tilting_table/plot_seed_spread.py [results/tilting_table] [out.png]

Plots every model that was run with several draws (collect_tilting_table.seed_groups with
DRAW), with its other packing sizes. A run that stood to its last stage is drawn at that stage
as a lower bound (^), one that failed in its first stage as an upper bound (v); neither enters
the mean. Wall times compare only between runs on one machine.
"""
import importlib.util
import os
import statistics
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

_spec = importlib.util.spec_from_file_location(
    "collect_tilting_table", os.path.join(os.path.dirname(os.path.abspath(__file__)), "collect_tilting_table.py"))
collect = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(collect)


def sized_groups(runs: dict[str, dict]) -> dict[tuple, dict[tuple, list[dict]]]:
    """Groups of draws (packing and layout seeds) by model (the key without rmin, rmax), for models
    with several draws at a size."""
    by_model: dict[tuple, dict[tuple, list[dict]]] = {}
    for key, group in collect.seed_groups(runs, collect.DRAW).items():
        by_model.setdefault(key.without_size(), {})[key] = group
    return {model: sizes for model, sizes in by_model.items() if max(map(len, sizes.values())) >= 2}


def draw(ax, key: tuple, group: list[dict], colour) -> None:
    failed = collect.failed_seeds(group)
    for s in group:
        tilt = s["failure_tilt_deg"]
        if tilt is None:
            ax.plot(s["wall_time"], s.get("stable_up_to_deg") or 0.0, "^", color=colour, mfc="none")
        elif collect.first_stage_failure(s):
            ax.plot(s["wall_time"], tilt, "v", color=colour, mfc="none")
    label = f"{key.size_text()} ({len(failed)} of {len(group)} draws failed)"
    ax.plot([s["wall_time"] for s in failed], [s["failure_tilt_deg"] for s in failed], "o", color=colour, label=label)
    if len(failed) >= 2:
        tilts = [s["failure_tilt_deg"] for s in failed]
        ax.errorbar(statistics.mean(s["wall_time"] for s in failed), statistics.mean(tilts),
                    yerr=statistics.stdev(tilts), fmt="s", color=colour, ms=9, capsize=6, mfc="white")


def main(folder: str, png: str) -> None:
    models = sized_groups(collect.load(folder))
    if not models:
        sys.exit(f"no model in {folder} was run with several seeds or layouts: nothing to plot")
    fig, axes = plt.subplots(len(models), 1, figsize=(7, 4 * len(models)), squeeze=False)
    for ax, sizes in zip(axes[:, 0], models.values()):
        first = next(iter(sizes.values()))[0]
        target = first["thesis"]["failure_tilt_deg"]
        ax.axhspan(target - collect.TARGET_TOLERANCE_DEG, target + collect.TARGET_TOLERANCE_DEG, color="0.85",
                   label=f"thesis {target}° ± {collect.TARGET_TOLERANCE_DEG:g}°")
        for (key, group), colour in zip(sorted(sizes.items(), key=lambda kv: -kv[0].rmax), plt.cm.tab10.colors):
            draw(ax, key, group, colour)
        name = collect.group_name(next(iter(sizes)))
        title = name.split(" R ")[0] + name.split(" mm", 1)[1]  # the model without its size
        ax.set_title(textwrap.fill(title, 100), fontsize=8)
        walls = [s["wall_time"] for group in sizes.values() for s in group]
        if max(walls) > 10 * min(walls):  # several packing sizes: their costs differ by decades
            ax.set_xscale("log")
        ax.set_xlabel("wall time of the run (s)")
        ax.set_ylabel("failure tilt (°)")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print(f"wrote {png}")


if __name__ == "__main__":
    folder = sys.argv[1] if len(sys.argv) > 1 else "results/tilting_table"
    main(folder, sys.argv[2] if len(sys.argv) > 2 else os.path.join(folder, "seed_spread.png"))
