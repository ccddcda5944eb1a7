"""Limit equilibrium from the command line, without YADE: reads a JSON file, prints a JSON result.

    python3 -m toppling.lem goodman-bray INPUT.json
    python3 -m toppling.lem flexural INPUT.json

The keys of each method are listed by ``python3 -m toppling.lem --help``; units: m, degrees,
N/m³ and Pa (or kN/m³ and kPa: forces then come out in kN), forces per metre of slope.
"""
from __future__ import annotations

import argparse
import json
import sys
from typing import Any

from toppling.lem import flexural, goodman_bray
from toppling.lem.geometry import SlopeGeometry
from toppling.lem.report import json_text

GEOMETRY = ("height", "face_deg", "top_deg", "joint_dip_deg", "failure_plane_deg", "spacing")
BLOCKS = ("heights", "width", "base_dip_deg", "a1", "a2", "crest")
HELP = f"""goodman-bray keys: either the blocks {', '.join(BLOCKS)} (crest optional: the tallest)
  or the slope {', '.join(GEOMETRY)}; and unit_weight, friction_deg, optional base_friction_deg
  (default friction_deg) and required_fs (then the toe force that gives it is printed too).
flexural keys: the slope {', '.join(GEOMETRY)}; unit_weight, tensile_strength, friction_deg,
  optional side_force_at (default 0.6)."""


def run_goodman_bray(inputs: dict[str, Any]) -> dict[str, Any]:
    _refuse_unknown(inputs, BLOCKS + GEOMETRY + ("unit_weight", "friction_deg", "base_friction_deg", "required_fs"))
    unit_weight, friction = _required(inputs, "unit_weight"), _required(inputs, "friction_deg")
    if "heights" in inputs:
        blocks = goodman_bray.Blocks(tuple(_required(inputs, "heights")), _required(inputs, "width"),
                                     _required(inputs, "base_dip_deg"), _required(inputs, "a1"),
                                     _required(inputs, "a2"), unit_weight, inputs.get("crest", 0))
    else:
        blocks = _geometry(inputs).blocks(unit_weight)
    out = goodman_bray.summary(blocks, friction, inputs.get("base_friction_deg"), per_block=True)
    out.update(a1=blocks.a1, a2=blocks.a2, crest=blocks.crest_block)
    if "required_fs" in inputs:
        out["toe_force_for_required_fs"] = goodman_bray.toe_support(blocks, friction, inputs["required_fs"])
    return out


def run_flexural(inputs: dict[str, Any]) -> dict[str, Any]:
    _refuse_unknown(inputs, GEOMETRY + ("unit_weight", "tensile_strength", "friction_deg", "side_force_at"))
    slope = _geometry(inputs)
    rock = flexural.Rock(_required(inputs, "unit_weight"), _required(inputs, "tensile_strength"),
                         _required(inputs, "friction_deg"), inputs.get("side_force_at", 0.6))
    return flexural.summary(slope, rock, per_column=True)


METHODS = {"goodman-bray": run_goodman_bray, "flexural": run_flexural}


def _geometry(inputs: dict[str, Any]) -> SlopeGeometry:
    return SlopeGeometry(**{k: _required(inputs, k) for k in GEOMETRY})


def _required(inputs: dict[str, Any], key: str) -> Any:
    if key not in inputs:
        raise ValueError(f"input key {key!r} is missing")
    return inputs[key]


def _refuse_unknown(inputs: dict[str, Any], known: tuple[str, ...]) -> None:
    unknown = sorted(set(inputs) - set(known))
    if unknown:
        raise ValueError(f"unknown input keys {unknown}; known: {sorted(known)}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python3 -m toppling.lem", description=__doc__.splitlines()[0],
                                     epilog=HELP, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("method", choices=sorted(METHODS))
    parser.add_argument("input", help="JSON file of inputs ('-' reads standard input)")
    args = parser.parse_args(argv)
    with (sys.stdin if args.input == "-" else open(args.input)) as f:
        inputs = json.load(f)
    try:
        result = METHODS[args.method](inputs)
    except ValueError as error:
        print(f"{args.method}: {error}", file=sys.stderr)
        return 2
    print(json_text(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
