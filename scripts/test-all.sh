#!/usr/bin/env bash
# Runs every test of gartowen: unit, property, integration, CLI end-to-end, doctests and the
# exhaustive 2^32-word float test (all in the test profile, opt-level 2), the Python package's
# pytest suite, then the Coq proofs
# when proofs/ has theories. Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."

# Prerequisites first: a missing tool stops the run in seconds, not after the tests.
scripts/prerequisites.sh
# Each phase is timed; the last line says where the time went (the README quotes it).
started=$(date +%s)
# lap VAR: seconds since the last lap into VAR (no subshell, so the clock moves on).
lap() { local now; now=$(date +%s); printf -v "$1" %d $(( now - started )); started=$now; }
cargo test --workspace --no-run -q
lap build_s
cargo test --workspace --no-fail-fast
lap rust_s

# The Python package: built with maturin into target/pyvenv, tested with pytest.
scripts/python-tests.sh
lap python_s

proofs_s=0
if [ -x proofs/check.sh ]; then
  proofs/check.sh
  lap proofs_s
fi
echo "test-all: building the Rust tests ${build_s} s, running them ${rust_s} s, the Python" \
  "package and pytest ${python_s} s, the proofs ${proofs_s} s"
