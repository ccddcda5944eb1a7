#!/usr/bin/env python3
"""Run every verification example and print their results as a Markdown table.

    python3 examples/verification/report.py     # after scripts/setup.sh; writes results/<case>/

Each case runs `./yade -x -n <example>` with a one-line readParamsFromTable table.
"""
import json
import os
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CASES = [  # (label, example, parameters)
    ("free fall: impact velocity (Table 4-1)", "free_fall", {}),
    ("restitution, beta = 0.13", "restitution", {"beta": 0.13}),
    ("restitution, beta = 0.5", "restitution", {"beta": 0.5}),
    ("cantilever: tip deflection (Tables 4-2/4-3)", "cantilever", {}),
    ("bond pulled: peak force", "bond_strength", {"load": "pull"}),
    ("bond bent: peak moment", "bond_strength", {"load": "bend"}),
    ("bond sheared: peak force", "bond_strength", {"load": "shear"}),
    ("bond sheared at 2 MPa compression", "bond_strength", {"load": "shear", "compression": 2e6}),
    ("strength reduction: block on a joint, FS = tan φ / tan α", "strength_reduction", {"alpha": 20.0, "phi": 30.0}),
]


def run(example: str, params: dict, out: str) -> dict:
    params = {**params, "out": out}
    table = os.path.join(out + ".table")
    os.makedirs(os.path.dirname(table), exist_ok=True)
    with open(table, "w") as f:
        f.write(" ".join(params) + "\n" + " ".join(repr(v) if isinstance(v, str) else str(v) for v in params.values()) + "\n")
    subprocess.run([os.path.join(REPO, "yade"), "-x", "-n", os.path.join(REPO, "examples", "verification", example + ".py")],
                   env=dict(os.environ, YADE_BATCH=f"{table}:2"), check=True, capture_output=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def main() -> int:
    print("| case | measured | reference | rel. error | notes |")
    print("|---|---|---|---|---|")
    for k, (label, example, params) in enumerate(CASES):
        s = run(example, params, os.path.join(REPO, "results", "verification", f"{k:02d}_{example}"))
        notes = []
        if "bounces" in s:
            notes.append(f"{s['bounces']} bounces, max height error {s['bounce_height_max_rel_error']:.1e}")
        if "mode" in s:
            notes.append(f"broke in {s['mode']}")
        if "bracket" in s:
            notes.append(f"bracket {s['bracket'][0]:.4f}-{s['bracket'][1]:.4f} after {len(s['trials'])} trials")
        if "thesis_hdpac_mm" in s:
            notes.append(f"thesis HDPAC {s['thesis_hdpac_mm']} mm")
        print(f"| {label} | {s['measured']:.6g} {s['unit']} | {s['reference']:.6g} {s['unit']} | "
              f"{s['rel_error']:.1e} | {'; '.join(notes)} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
