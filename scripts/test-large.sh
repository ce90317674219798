#!/usr/bin/env bash
# The large tier: the size sweeps the test command (scripts/test-all.sh) runs at smaller sizes,
# at their full sizes. They are the tests marked `#[ignore = "large tier …"]`; each has a
# smaller twin in the test command that checks the same fact. Extra arguments go to the test
# binaries (e.g. a test name filter). Without arguments it then seeds the planted bugs of
# tests/planted into the checker and requires the differential tests to see each
# (scripts/planted-bugs.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo test --workspace --no-fail-fast -- --ignored "$@"
if [ $# -eq 0 ]; then
  scripts/planted-bugs.sh
fi
