#!/usr/bin/env bash
# The test command: set up (if needed; cached) and run the fast tests:
# C++ unit tests through CTest and physics tests through pytest inside YADE's Python.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$repo/scripts/setup.sh"
ctest --test-dir "$repo/build" --output-on-failure
source "$repo/scripts/env.sh"
cd "$repo" && /usr/bin/python3 -m pytest -q tests/python "$@"
