#!/usr/bin/env bash
# Builds the Python package into a virtual environment (target/pyvenv) with pip, the way a
# user installs it (`pip install ./python`), then runs its pytest suite against the CLI built
# by `cargo test` (target/debug/gartowen). Needs python3 ≥ 3.9 with venv, and PyPI for
# maturin, numpy, scipy, pytest and pytest-xdist on the first run.
# Usage: python-tests.sh [--dependencies]   (--dependencies: only the venv and PyPI's packages,
# which scripts/test-all.sh fetches while cargo compiles)
set -euo pipefail
cd "$(dirname "$0")/.."

venv=target/pyvenv
if [ ! -x "$venv/bin/python" ]; then
  python3 -m venv "$venv" || {
    echo "python-tests: cannot create a virtual environment (Debian: apt-get install python3-venv)" >&2
    exit 1
  }
fi
export PATH="$PWD/$venv/bin:$PATH"
# Mitsuba 3 for the rendering tests (gartowen.mitsuba, gartowen.render; libLLVM comes from
# scripts/prerequisites.sh).
python -m pip install -q --disable-pip-version-check "maturin>=1.9,<2" numpy scipy pytest pytest-xdist "mitsuba>=3.5"
[ "${1:-}" = --dependencies ] && exit 0
# Built in the dev profile (opt-level 2, as the tests) with the feature test-build (the features
# the test build unifies, python/Cargo.toml), so it reuses the test build's crates and compiles
# only pyo3, numpy and the package itself; a user's `pip install ./python` builds release.
MATURIN_PEP517_ARGS="--profile dev --features test-build" \
  python -m pip install -q --disable-pip-version-check --no-build-isolation ./python

if [ -z "${GARTOWEN_BIN:-}" ]; then
  [ -x target/debug/gartowen ] || cargo build -q -p gartowen-cli
  export GARTOWEN_BIN="$PWD/target/debug/gartowen"
fi
# From the tests folder, so the installed package (not python/gartowen) is the one imported.
# One pytest worker per core (pytest-xdist): on 2 cores the suite took 82 s with one worker and
# 51 s with two (record/2026-12-08-ci.md).
cd python/tests
python -m pytest -q -p no:cacheprovider -n auto .
