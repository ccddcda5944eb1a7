"""The equivalent slope by limit equilibrium, beside a DEM run of it: Goodman and Bray on its
blocks, Aydan and Kawamoto on its columns, cut along the failure plane the run found (or the
thesis' 15° when no run is given or it stood). Prints JSON; needs no YADE.

    source scripts/env.sh; python3 examples/equivalent_slope/lem.py [results/equivalent_slope/base]

The rock: Table 5-5's density; the columns' tensile strength is the parallel bonds' (times the
run's strength factor), an upper bound of the bonded rock's; the joints' friction Table 5-6's
(the run's main-joint friction when given).
"""
import json
import math
import os
import sys

from examples import params
from toppling.lem import flexural, goodman_bray
from toppling.lem.geometry import SlopeGeometry
from toppling.lem.report import json_text

G = 9.81  # m/s2


def dem_result(run: str | None) -> dict | None:
    if run is None:
        return None
    with open(os.path.join(run, "summary.json")) as f:
        summary = json.load(f)
    keys = ("failed", "phi_overall_deg", "s_over_h", "t_over_h", "stable_zone_columns")
    return {"inputs": summary["inputs"], **{k: summary.get(k) for k in keys}}


def main(run: str | None) -> dict:
    dem = dem_result(run)
    inputs = {**params.EQUIVALENT_SLOPE, **(dem["inputs"] if dem else {})}
    plane = dem["phi_overall_deg"] if dem and dem["failed"] and dem["phi_overall_deg"] is not None else \
        params.EQUIVALENT_SLOPE_RESULTS["phi_deg"][0]
    slope = SlopeGeometry.from_slope_shape(max(plane, 0.0), **params.EQUIVALENT_SLOPE_SHAPE)
    unit_weight = params.TABLE_5_5["density"] * G
    side_friction = math.degrees(math.atan(inputs["main_joint_friction"]))
    base_friction = math.degrees(math.atan(params.TABLE_5_6["base"][1]))
    rock = flexural.Rock(unit_weight, params.TABLE_5_5["bondTensileStrength"] * inputs["strength_factor"],
                         side_friction)
    return dict(failure_plane_deg=slope.failure_plane_deg, slope=vars(slope),
                goodman_bray=goodman_bray.summary(slope.blocks(unit_weight), side_friction, base_friction),
                flexural=flexural.summary(slope, rock),
                dem=dem and {k: v for k, v in dem.items() if k != "inputs"})


if __name__ == "__main__":
    print(json_text(main(sys.argv[1] if len(sys.argv) > 1 else None)))
