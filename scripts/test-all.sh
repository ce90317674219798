#!/usr/bin/env bash
# Runs every test of gartowen: unit, property, integration, CLI end-to-end, doctests and the
# exhaustive 2^32-word float test (in the test profile: the libraries at opt-level 2), the
# Python package's pytest suite, then the Coq proofs when proofs/ has theories. Exits non-zero
# when any part fails.
#
# On 2 cores the parts overlap where they would leave a core idle: PyPI's downloads for the
# Python package and the extracted driver are built while cargo compiles, and the proofs (coqc,
# one core, on a copy of the sources in a temporary folder, reusing the theories
# proofs/extract.sh built) run beside the Python package's build and pytest.
set -euo pipefail
cd "$(dirname "$0")/.."

# Prerequisites first: a missing tool stops the run in seconds, not after the tests.
scripts/prerequisites.sh
logs=target/test-all
mkdir -p "$logs"
background=()
# A failure in the foreground ends the run: stop what still runs beside it.
trap 'for p in "${background[@]}"; do kill "$p" 2>/dev/null || true; done' EXIT
# finish PID NAME LOG: waits for a background part; on failure shows its log and stops.
finish() {
  if ! wait "$1"; then
    sed 's/^/  /' "$3" >&2
    echo "test-all: $2 FAILED (its output above, kept in $3)" >&2
    exit 1
  fi
}

# Each phase is timed; the last line says where the time went (the README quotes it).
started=$(date +%s)
# lap VAR: seconds since the last lap into VAR (no subshell, so the clock moves on).
lap() { local now; now=$(date +%s); printf -v "$1" %d $(( now - started )); started=$now; }

scripts/python-tests.sh --dependencies > "$logs/python-dependencies.log" 2>&1 &
dependencies_pid=$!
background+=("$dependencies_pid")
# The OCaml driver extracted from the proofs, which the Rust tests run (proofs/extract.sh: about
# 30 s of coqc on one core), is built beside the Rust build: built by the first test that needs
# it, it held both test threads while one core compiled. A failure here is left to those tests,
# which build it again and say why (or skip loudly under GARTOWEN_SKIP_PROOFS=1).
extract_pid=
if command -v coqc >/dev/null && command -v ocamlopt >/dev/null; then
  proofs/extract.sh target/extracted > "$logs/extract.log" 2>&1 &
  extract_pid=$!
  background+=("$extract_pid")
fi
cargo test --workspace --no-run -q
if [ -n "$extract_pid" ]; then wait "$extract_pid" || true; fi
lap build_s
cargo test --workspace --no-fail-fast
lap rust_s
finish "$dependencies_pid" "the Python package's dependencies" "$logs/python-dependencies.log"

# Not beside the Rust tests: some of them bound how long a stalled program takes to be killed,
# and a third busy process on two cores pushed one past its bound.
proofs_pid=
if [ -x proofs/check.sh ]; then
  proofs/check.sh > "$logs/proofs.log" 2>&1 &
  proofs_pid=$!
  background+=("$proofs_pid")
fi
# The Python package: built with maturin into target/pyvenv, tested with pytest.
scripts/python-tests.sh
lap python_s
proofs_after=0
if [ -n "$proofs_pid" ]; then
  finish "$proofs_pid" "the proofs" "$logs/proofs.log"
  cat "$logs/proofs.log"
  lap proofs_after
fi
echo "test-all: building the Rust tests ${build_s} s, running them ${rust_s} s, the Python" \
  "package and pytest ${python_s} s with the proofs beside them, the proofs ${proofs_after} s more"
