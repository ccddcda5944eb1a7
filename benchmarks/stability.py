"""Stability map: where the methods fail, shown rather than assumed (docs/performance.md).

``timestep``: thesis Table 4-6's block (it topples), run at each time-step safety (the time
stepper's coefficient of sqrt(2 m / K), K a body's summed contact stiffness: a lower bound of
the critical step) x joint stiffness scale x damping (none; contact only, Table 5-6's
dashpots; local 0.7 alone). A cell is, first match: "unstable" (stopped by the laws'
instability detector; its message kept), "nan" (a position not finite: must never happen),
"drift" (the mechanical energy rose more than 1 % of the block's m g h above its start: damping,
friction and breaks only lower it), "answer" (a mode other than the thesis' topple), "ok".

``interlock``: §4.4's block sliding on a frictionless incline (b = h = 0.2 m, 15°: it cannot topple),
across a smooth joint or plain disc contacts, at block width / Rmax 3 ... 20, 5 packings
each, porosity 0.25 (0.2 cannot be packed at 3 without locked-in stress) and bonds within 0.5
Rmin (within 0.05, the default, most coarse discs of so loose a packing stay unbonded and the
"block" is a few loose pieces): right if it slides at g sin α within 10 % without turning (5°,
the discs' mean rotation); coarse discs across plain contacts interlock.

    ./yade -x -n -j1 benchmarks/stability.py [timestep|interlock]   # both by default
Writes results/stability/<study>.csv and .png and prints a Markdown table.
"""
import csv
import math
import sys

import numpy as np
from yade import O
from yade.wrapper import GlobalStiffnessTimeStepper

from examples import params
from toppling.analyse import energy
from toppling.build import engines
from toppling.io import output
from toppling.load import tilting
from toppling.models import incline

OUT = "results/stability"
SAFETIES = (0.3, 0.6, 0.9, 1.2, 1.6, 2.0)  # the 0.3-1.2, then on to where it breaks
JOINT_SCALES = (0.01, 0.1, 1.0)
DAMPING = {"none": (0.0, 0.0, 0.0), "contact": (0.13, 0.2, 0.0), "local 0.7": (0.0, 0.0, 0.7)}  # contact, bond, local
WIDTHS = (3, 4, 6, 8, 12, 16, 20)  # block width / Rmax
SEEDS = (1, 2, 3, 4, 5)


def block(b, h, alpha, phi, rmax, seed=1, smooth=True, joint_scale=1.0, damping="contact", porosity=0.2,
          bond_gap=incline.BOND_GAP):
    """Table 5-6's rock with the chosen dashpots, tilted to ``alpha``; the scene's block."""
    contact, bond, local = DAMPING[damping]
    rock = {**params.TABLE_5_6_ROCK, "normalDamping": contact, "bondNormalDamping": bond}
    setup = incline.build(b, h, rmax / params.PACKING_R_RATIO, rmax, rock, phi, smooth=smooth, seed=seed,
                          joint_stiffness_scale=joint_scale, porosity=porosity, bond_gap=bond_gap)
    engines.set_local_damping(local)
    tilting.set_tilt(alpha)
    return setup


def set_safety(safety: float) -> float:
    """The time stepper's coefficient, beyond the (0, 1] engines.engines allows; dt / the law's estimate."""
    stepper = next(e for e in O.engines if isinstance(e, GlobalStiffnessTimeStepper))
    estimate = engines.bond_law().criticalTimeStep()
    stepper.timestepSafetyCoefficient, stepper.defaultDt, stepper.previousDt = safety, safety * estimate, safety * estimate
    O.dt = safety * estimate
    return O.dt / estimate


def timestep_cell(safety: float, joint_scale: float, damping: str) -> dict:
    t = params.TABLE_4_6
    O.reset()
    setup = block(t["b"], t["h"], t["alpha"], t["phi"], 0.008, joint_scale=joint_scale, damping=damping)
    ratio = set_safety(safety)
    scale = sum(O.bodies[i].state.mass for i in setup.block) * engines.G * t["h"]
    e0, rises = energy.mechanical(), [0.0]
    row = dict(safety=safety, joint_scale=joint_scale, damping=damping, dt_over_estimate=ratio, message="")
    try:
        history = incline.run_to_mode(setup, 2.0, on_chunk=lambda: rises.append(energy.mechanical() - e0))
        row.update(mode=incline.mode(history[-1][1], history[-1][2], t["b"]), simulated_s=history[-1][0])
    except RuntimeError as e:
        row.update(mode="", simulated_s=O.time, message=str(e))
    finite = all(np.isfinite(tuple(b.state.pos)).all() for b in O.bodies if b is not None)
    row.update(drift=max(rises) / scale, steps=O.iter)
    row["cell"] = ("unstable" if row["message"] else "nan" if not finite else "drift" if row["drift"] > 0.01
                   else "answer" if row["mode"] != "topple" else "ok")
    return row


def interlock_cell(width: float, smooth: bool, seed: int) -> dict:
    b, h, alpha = 0.2, 0.2, 15.0
    O.reset()
    row = dict(width_over_rmax=width, smooth=int(smooth), seed=seed)
    try:
        setup = block(b, h, alpha, 0.0, b / width, seed=seed, smooth=smooth, porosity=0.25, bond_gap=0.5)
    except ValueError as e:  # too few discs to make a block
        return dict(row, block_discs=0, mode=str(e), acceleration_ratio=float("nan"), steps=0, right=0)
    history = incline.run_to_mode(setup, 0.5)
    t, x, spin = history[-1]
    expected = engines.G * math.sin(math.radians(alpha))
    row.update(block_discs=len(setup.block), mode=incline.mode(x, spin, b), acceleration_ratio=2 * x / t**2 / expected,
               steps=O.iter)
    row["right"] = int(row["mode"] == "slide" and abs(row["acceleration_ratio"] - 1) < 0.1)
    return row


def write(study: str, rows: list[dict]) -> None:
    with open(f"{output.output_dir(OUT)}/{study}.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


def timestep_map(rows: list[dict]) -> None:
    colours = {"ok": 0, "answer": 1, "drift": 2, "unstable": 3, "nan": 4}
    fig, axes = output.plt.subplots(1, len(DAMPING), figsize=(12, 3.6), sharey=True)
    for ax, damping in zip(axes, DAMPING):
        grid = np.array([[colours[r["cell"]] for r in rows if r["damping"] == damping and r["joint_scale"] == k]
                         for k in JOINT_SCALES])
        ax.imshow(grid, cmap="RdYlGn_r", vmin=0, vmax=4, origin="lower", aspect="auto")
        for r in (r for r in rows if r["damping"] == damping):
            ax.text(SAFETIES.index(r["safety"]), JOINT_SCALES.index(r["joint_scale"]), r["cell"], ha="center",
                    va="center", fontsize=7)
        ax.set(xticks=range(len(SAFETIES)), xticklabels=SAFETIES, xlabel="time-step safety", title=f"damping: {damping}")
    axes[0].set(yticks=range(len(JOINT_SCALES)), yticklabels=JOINT_SCALES, ylabel="joint stiffness scale")
    output.save_figure(fig, OUT, "timestep")
    print("| damping | joint scale | " + " | ".join(f"safety {s}" for s in SAFETIES) + " |")
    print("|---|---|" + "---|" * len(SAFETIES))
    for damping in DAMPING:
        for k in JOINT_SCALES:
            cells = [r for r in rows if r["damping"] == damping and r["joint_scale"] == k]
            print(f"| {damping} | {k} | " + " | ".join(f"{r['cell']} ({100 * r['drift']:.2g} %)" for r in cells) + " |")


def interlock_chart(rows: list[dict]) -> None:
    fig, ax = output.figure("block width / Rmax", f"packings right (of {len(SEEDS)})", "Sliding block, frictionless joint")
    for smooth in (1, 0):
        right = [sum(r["right"] for r in rows if r["width_over_rmax"] == w and r["smooth"] == smooth) for w in WIDTHS]
        ax.plot(WIDTHS, right, "o-", label="smooth joint" if smooth else "plain contacts")
    ax.legend()
    output.save_figure(fig, OUT, "interlock")
    print("| width / Rmax | block discs | smooth joint: right | a / g sin α | plain contacts: right | a / g sin α |\n"
          "|---|---|---|---|---|---|")
    for w in WIDTHS:
        built = [r for r in rows if r["width_over_rmax"] == w and r["block_discs"]]
        cells = [f"{np.mean([r['block_discs'] for r in built]):.0f}" if built else "-"]
        for smooth in (1, 0):
            mine = [r for r in built if r["smooth"] == smooth]
            ratios = [r["acceleration_ratio"] for r in mine]
            spread = f"{np.mean(ratios):.3f} ± {np.std(ratios, ddof=1):.3f}" if len(ratios) > 1 else "-"
            no_block = len(SEEDS) - len(mine)
            cells += [f"{sum(r['right'] for r in mine)}" + (f" ({no_block} no block)" if no_block else ""), spread]
        print(f"| {w} | " + " | ".join(cells) + " |")


STUDIES = {
    "timestep": (lambda: [timestep_cell(s, k, d) for d in DAMPING for k in JOINT_SCALES for s in SAFETIES], timestep_map),
    "interlock": (lambda: [interlock_cell(w, s, seed) for w in WIDTHS for s in (True, False) for seed in SEEDS],
                  interlock_chart),
}



def main(studies: list[str]) -> None:
    for study in studies or STUDIES:
        cells, show = STUDIES[study]
        found = cells()
        write(study, found)
        show(found)


if __name__ == "__main__":
    main(sys.argv[1:])
