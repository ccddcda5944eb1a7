"""The four families of thesis §5.3.3 beside the thesis: one row per case (ours mean ± sd over
its packing seeds, the thesis' figures from records/thesis_families.csv), the issue's checks, and
the figures Fig 5-25 (against D/H) and Fig 5-29 (against the main joints' friction), and what the
runs cost by family.

    source scripts/env.sh; /usr/bin/python3 calibration/equivalent_slope/families_report.py [results/equivalent_slope/families]

Ours come from the families' record (record.py), which the folder's finished runs are first
added to. A case stands when most of its seeds stand (no failure). Writes fig_5_25.png and
fig_5_29.png into the results folder.
"""
import csv
import os
import statistics
import sys

import matplotlib.pyplot as plt
from scipy import stats

import record
from collect import mean_sd  # this folder's: runs as a script
from toppling.io import output

THESIS = os.path.join(os.path.dirname(__file__), "records", "thesis_families.csv")
FRICTION_TREND = [f"t510_{k}" for k in range(2, 9)]  # Table 5-10 cases 2-8: φ rises with Jφ


def thesis_cases() -> dict[str, dict]:
    with open(THESIS) as f:
        return {row["case"]: row for row in csv.DictReader(f)}


def by_case(rows: dict[str, dict]) -> dict[str, list[dict]]:
    """The record's rows by case (a run's name without its seed)."""
    found: dict[str, list[dict]] = {}
    for name, r in rows.items():
        found.setdefault(name.rsplit("_s", 1)[0], []).append(r)
    return found


def values(runs: list[dict], key: str) -> list[float]:
    return [s[key] for s in runs if s.get("failed") and s.get(key) is not None]


def stands(runs: list[dict]) -> bool:
    return sum(not s.get("failed") for s in runs) > len(runs) / 2


def table(cases: dict[str, dict], ours: dict[str, list[dict]]) -> int:
    """Print the comparison; returns how many family cases (the base model aside) agree on
    standing or failing."""
    print("| case | seeds | stands: ours / thesis | planes: ours / thesis | φ (°) ours | thesis | S/H ours | thesis | "
          "T/H ours | thesis |\n|---|---|---|---|---|---|---|---|---|---|")
    agree = 0
    for name, t in cases.items():
        runs = ours.get(name, [])
        if not runs:
            print(f"| {t['label']} | 0 | not run | | | | | | | |")
            continue
        agree += name != "base" and stands(runs) == (t["stands"] == "1")
        planes = "/".join(str(int(s["planes"] or 0)) for s in runs)
        print(f"| {t['label']} | {len(runs)} | {sum(not s.get('failed') for s in runs)} of {len(runs)} / "
              f"{'yes' if t['stands'] == '1' else 'no'} | {planes} / {t['planes']} | "
              f"{mean_sd(values(runs, 'phi_overall_deg'), 1)} | {t['phi_deg'] or '-'} | "
              f"{mean_sd(values(runs, 's_over_h'), 2)} | {t['s_over_h'] or '-'} | "
              f"{mean_sd(values(runs, 't_over_h'), 2)} | {t['t_over_h'] or '-'} |")
    return agree


def friction_trend(ours: dict[str, list[dict]]) -> list[float]:
    """Spearman's rank correlation of φ with Jφ over Table 5-10 cases 2-8, one per packing seed."""
    per_seed: dict[int, list[tuple[float, float]]] = {}
    for case in FRICTION_TREND:
        for name, runs in ours.items():
            if name.startswith(case + "_mu"):
                for s in runs:
                    if s.get("failed") and s.get("phi_overall_deg") is not None:
                        per_seed.setdefault(s["seed"], []).append((s["main_joint_friction"], s["phi_overall_deg"]))
    return [stats.spearmanr(*zip(*pairs))[0] for pairs in per_seed.values() if len(pairs) > 2]


def figure(cases: dict[str, dict], ours: dict[str, list[dict]], table_name: str, xlabel: str, out: str, file: str):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    fig.suptitle(f"Table {table_name}: ours (mean ± sd over seeds) and the thesis'")
    for ax, label in zip(axes, ("φ (°)", "S/H, T/H")):
        ax.set_xlabel(xlabel)
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    for case, t in cases.items():
        if t["table"] != table_name or not t["x"]:
            continue
        x, runs = float(t["x"]), ours.get(case, [])
        for key, ax, marker in (("phi_overall_deg", axes[0], "o"), ("s_over_h", axes[1], "s"), ("t_over_h", axes[1], "^")):
            xs = values(runs, key)
            if xs:
                ax.errorbar(x, statistics.mean(xs), yerr=statistics.stdev(xs) if len(xs) > 1 else 0, fmt=marker,
                            color="C0", capsize=3)
            thesis = t["phi_deg" if key == "phi_overall_deg" else key]
            if thesis:
                ax.plot(x, float(thesis), marker, color="C3", mfc="none")
    axes[0].plot([], [], "o", color="C0", label="ours")
    axes[0].plot([], [], "o", color="C3", mfc="none", label="thesis")
    axes[1].plot([], [], "s", color="k", mfc="none", label="S/H")
    axes[1].plot([], [], "^", color="k", mfc="none", label="T/H")
    for ax in axes:
        ax.legend()
    output.save_figure(fig, out, file)


def cost(cases: dict[str, dict], ours: dict[str, list[dict]]) -> None:
    """Wall time and steps per run, by family (the thesis' table a case comes from)."""
    print("| family | runs | wall (s), median | range | steps, median |\n|---|---|---|---|---|")
    families: dict[str, list[dict]] = {}
    for name, t in cases.items():
        families.setdefault("base model" if name == "base" else f"Table {t['table']}", []).extend(ours.get(name, []))
    for family, runs in families.items():
        if runs:
            wall, steps = [r["wall_time"] for r in runs], [r["steps"] for r in runs]
            print(f"| {family} | {len(runs)} | {statistics.median(wall):.0f} | {min(wall):.0f}–{max(wall):.0f} | "
                  f"{statistics.median(steps):,.0f} |")


def main(folder: str) -> None:
    os.makedirs(folder, exist_ok=True)
    cases, ours = thesis_cases(), by_case(record.update(folder))
    agree = table(cases, ours)
    run = sum(1 for name in cases if name != "base" and ours.get(name))
    print(f"\nstand or fail as the thesis: {agree} of the {run} family cases run (the issue asks at least 28 of 32)")
    trend = friction_trend(ours)
    print(f"φ against Jφ over Table 5-10 cases 2-8, Spearman per seed: {', '.join(f'{r:.2f}' for r in trend) or '-'}"
          f" (the issue asks > 0.5)")
    print()
    cost(cases, ours)
    figure(cases, ours, "5-7", "D/H", folder, "fig_5_25")
    figure(cases, ours, "5-10", "main joints' friction coefficient", folder, "fig_5_29")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "results/equivalent_slope/families")
