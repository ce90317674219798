#!/usr/bin/env bash
# Runs every test of gartowen: unit, property, integration, CLI end-to-end, doctests and the
# exhaustive 2^32-word float test (all in the test profile, opt-level 2), the Python package's
# pytest suite, then the Coq proofs
# when proofs/ has theories. Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."

# Prerequisites first: a missing tool stops the run in seconds, not after the tests.
scripts/prerequisites.sh

cargo test --workspace --no-fail-fast

# The Python package: built with maturin into target/pyvenv, tested with pytest.
scripts/python-tests.sh

if [ -x proofs/check.sh ]; then
  proofs/check.sh
fi
