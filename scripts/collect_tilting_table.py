"""Collect the tilting-table summaries into one comparison table (ours vs thesis Table 5-4).

    python3 scripts/collect_tilting_table.py [results/tilting_table]

Prints a Markdown table (pasted into README.md) from every ``<folder>/*/summary.json``.
"""
import glob
import json
import os
import sys


CALIBRATION = ("bond_tensile_strength", "main_joint_friction", "base_joint_friction")  # 0: the thesis' tables


def fmt(value, digits=1):
    if value is None:
        return "-"
    if isinstance(value, list):
        return ", ".join(fmt(v, digits) for v in value) or "-"
    return f"{value:.{digits}f}"


def main(folder: str) -> None:
    rows = []
    for path in sorted(glob.glob(os.path.join(folder, "*", "summary.json"))):
        with open(path) as f:
            s = json.load(f)
        inputs = s["inputs"]
        tilt = fmt(s["failure_tilt_deg"]) if s["failure_tilt_deg"] is not None else \
            f"none up to {fmt(s.get('stable_up_to_deg'))}"
        stable = [stage["tilt"] for stage in s["stages"] if stage["outcome"] == "equilibrium"]
        changed = ", ".join(f"{name} {inputs[name]:g}" for name in CALIBRATION if inputs.get(name)) or "Tables 5-2/5-3"
        rows.append(f"| {os.path.basename(os.path.dirname(path))} | {inputs['arrangement']} | {changed} | "
                    f"{1e3 * inputs['rmin']:g}–{1e3 * inputs['rmax']:g} | {s['discs']} | "
                    f"{fmt(max(stable)) if stable else '-'} | {tilt} | {fmt(s['thesis']['failure_tilt_deg'])} | {fmt(s['phi_deg'])} | "
                    f"{fmt(s['thesis']['phi_deg'])} | {fmt(s['s_over_h'], 2)} | {fmt(s['t_over_h'], 2)} | "
                    f"{s['tensile_breaks']} / {s['shear_breaks']} | {s['wall_time']:.0f} |")
    if not rows:
        sys.exit(f"no {folder}/*/summary.json: run the tilting_table batch first (see README)")
    print("| run | arrangement | parameters | R (mm) | discs | last equilibrium (°) | failure tilt (°) | thesis (°) | φ (°) | thesis φ (°) | S/H | T/H "
          "| tensile / shear breaks | wall time (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    print("\n".join(rows))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "results/tilting_table")
