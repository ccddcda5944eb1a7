#!/usr/bin/env bash
# The test command: set up (if needed; cached) and run the fast tests: C++ unit tests
# through CTest, physics tests through pytest inside YADE's Python, and YADE's own suites
# (--test, --check: JCFpm's check included) to prove the plugin breaks nothing.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$repo/scripts/setup.sh"
ctest --test-dir "$repo/build" --output-on-failure
source "$repo/scripts/env.sh"
cd "$repo"
/usr/bin/python3 -m pytest -q tests/python tests/calibration "$@"
./yade --test > build/yade-test.log 2>&1 || { tail -40 build/yade-test.log; echo "YADE's --test failed" >&2; exit 1; }
./yade --check > build/yade-check.log 2>&1 || { tail -40 build/yade-check.log; echo "YADE's --check failed" >&2; exit 1; }
grep -q 'ALL TESTS PASSED' build/yade-test.log && grep -q 'ALL CHECKS PASSED' build/yade-check.log
echo "YADE --test and --check: passed"
