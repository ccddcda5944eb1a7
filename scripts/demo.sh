#!/usr/bin/env bash
# Set up (if needed) and run the main demo: a toppling slope end to end (the calibrated ideal
# tilting table at a coarse packing, R 2-8 mm, about 3 min), then the verification cases.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$repo/scripts/setup.sh"
cd "$repo"

echo "== the tilting table (thesis §5.2), ideal arrangement, R 2-8 mm: cases.table's 'demo' line"
cases=examples/tilting_table/cases.table
line=$(grep -n '^demo ' "$cases" | cut -d: -f1)
YADE_BATCH="$cases:$line" ./yade -x -n -j1 examples/tilting_table/run.py | grep -v '^\['
source scripts/env.sh
/usr/bin/python3 - results/tilting_table/demo <<'EOF'
import sys
from toppling.io.reader import read_run

run = read_run(sys.argv[1])
s = run["summary"]
if s["failed"]:
    print(f"failed at {s['failure_tilt_deg']:.0f} deg (thesis {s['thesis']['failure_tilt_deg']}), "
          f"phi {', '.join(f'{p:.1f}' for p in s['phi_deg']) or '-'} deg (thesis {s['thesis']['phi_deg']})")
    print("zones at the onset: " + ", ".join(f"{c} {z}" for c, z in s["onset"]["zones"].items()))
else:
    print(f"stood up to {s['stable_up_to_deg']:.0f} deg")
print(f"summary:  {sys.argv[1]}/summary.json")
print("pictures: " + " ".join(run["pictures"]))
print("ParaView: " + " ".join(run["paraview"].values()))
EOF

echo "== the verification cases (thesis chapter 4)"
/usr/bin/python3 examples/verification/report.py
