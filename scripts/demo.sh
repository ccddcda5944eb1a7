#!/usr/bin/env bash
# Set up (if needed) and run the main demo: the verification examples, each writing
# results/<name>/summary.json and a PNG.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$repo/scripts/setup.sh"
cd "$repo"
for example in free_fall restitution cantilever bond_strength block_on_incline tilt_slide; do
  ./yade -x -n "examples/verification/$example.py"
done
