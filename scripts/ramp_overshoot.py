"""How far the ramp to the start tilt overshoots the static load it brings the slope to.

Builds the tilting-table model of examples/tilting_table.py (its own build()) with bonds that do
not break at these tilts, brings it to rest on the level table (local damping 0.7, as the
example), ramps the tilt to ``tilt`` [deg] at ``rate`` [deg/s] with NewtonIntegrator's local
damping ``damping``, holds the tilt for ``hold`` [s] without local damping (the stages'), then
lets it come to rest with local damping 0.7: the static state at that tilt. Prints, every 0.02 s,
the largest downslope displacement of a column top since the level table and the largest bond
tensile stress, and then their peaks over the ramp and hold against the static values: a ratio
above 1 is the dynamic overshoot, the load a slope sees beyond the static one at that tilt.

    ./yade -x -n -j1 scripts/ramp_overshoot.py [rmin rmax tilt rate damping [seed [hold]]]
"""
import os
import sys

import numpy as np
from yade import O

from toppling import scene, tilting

sys.path.insert(0, os.path.join(os.environ["TOPPLING_REPO"], "scripts"))  # set by the ./yade launcher
from tilting_table_model import definitions  # noqa: E402

STRONG = 209e3  # Table 5-2's bond tensile strength: no bond of the ideal model breaks below 42 deg at it
SETTLE_DAMPING, SETTLE_TIME, REST_TIME = 0.7, 0.15, 0.5


def largest_bond_tension() -> float:
    return max((i.phys.bondSigmaMax for i in O.interactions
                if i.isReal and getattr(i.phys, "bondState", 0) == 1), default=0.0)


def top_shift(watched: list, reference: np.ndarray) -> float:
    """The largest downslope (x) displacement of a watched column top since ``reference``."""
    return float((tilting.medians(watched) - reference)[:, 0].max())


def main() -> None:
    args = [float(a) for a in sys.argv[1:]]
    rmin, rmax, tilt, rate, damping = args[:5] if len(args) >= 5 else (2e-3, 8e-3, 26.0, 50.0, 0.0)
    seed = int(args[5]) if len(args) >= 6 else 1
    hold = args[6] if len(args) >= 7 else 1.0
    model = definitions(arrangement="'ideal'", rmin=rmin, rmax=rmax, seed=seed, joint_stiffness_scale=0.01,
                        bond_tensile_strength=STRONG, shrink_overlaps=1)
    layout = model["build"]()
    watched = list(model["column_top_bands"](model["column_members"](layout), 2 * rmax).values())
    scene.set_local_damping(SETTLE_DAMPING)
    scene.run_steps(int(SETTLE_TIME / O.dt))
    reference = tilting.medians(watched)
    history = []

    def record() -> None:
        history.append((O.time, tilting.current_tilt(), top_shift(watched, reference), largest_bond_tension()))
        print(f"t = {O.time:.3f} s  tilt {history[-1][1]:.1f} deg  top {1e3 * history[-1][2]:.3f} mm  "
              f"bond {1e-3 * history[-1][3]:.1f} kPa", flush=True)

    scene.set_local_damping(damping)
    tilting.ramp(0.0, tilt, tilt / rate, record)
    scene.set_local_damping(0.0)
    end = O.time + hold
    while O.time < end:
        scene.run_steps(int(0.02 / O.dt))
        record()
    scene.set_local_damping(SETTLE_DAMPING)
    scene.run_steps(int(REST_TIME / O.dt))
    static_top, static_bond = top_shift(watched, reference), largest_bond_tension()
    peak_top, peak_bond = max(h[2] for h in history), max(h[3] for h in history)
    print(f"R {1e3 * rmin:g}-{1e3 * rmax:g} mm seed {seed}, ramp to {tilt:g} deg at {rate:g} deg/s, local damping "
          f"{damping:g}: top {1e3 * peak_top:.3f} mm peak / {1e3 * static_top:.3f} mm static = "
          f"{peak_top / static_top:.2f}; bond {1e-3 * peak_bond:.1f} / {1e-3 * static_bond:.1f} kPa = "
          f"{peak_bond / static_bond:.2f}")


main()
