#!/usr/bin/env bash
# Checks, within seconds and before anything is built, what the test command and the main job
# need: cargo, a C compiler (the external examples), python3 ≥ 3.9 with venv and libLLVM ≥ 16
# (Mitsuba's LLVM variant, for the rendering tests), and for the proofs coqc with Flocq and
# ocamlopt. As root on Debian/Ubuntu it installs what is missing
# and required (saying so first) with apt-get; otherwise (or with GARTOWEN_NO_INSTALL=1) it
# stops with the exact install line.
# GARTOWEN_SKIP_PROOFS=1 leaves out the Coq and OCaml tools (the proofs then say loudly that
# they were not checked); GARTOWEN_SKIP_PYTHON=1 leaves out Python (the main job needs none).
set -uo pipefail
cd "$(dirname "$0")/.."

missing=()
have() { command -v "$1" >/dev/null 2>&1; }

have cargo || {
  echo "prerequisites: cargo is missing: install the Rust toolchain (https://rustup.rs)" >&2
  exit 1
}
have cc || missing+=(gcc)
if [ "${GARTOWEN_SKIP_PYTHON:-0}" = 1 ]; then
  :
elif have python3 && python3 -c 'import sys; sys.exit(sys.version_info < (3, 9))' 2>/dev/null; then
  python3 -c 'import venv, ensurepip' 2>/dev/null || missing+=(python3-venv)
else
  missing+=(python3 python3-venv)
fi
# Mitsuba's LLVM variant (the rendering tests of the Python package) needs libLLVM ≥ 16.
if [ "${GARTOWEN_SKIP_PYTHON:-0}" != 1 ] && [ -z "${DRJIT_LIBLLVM_PATH:-}" ]; then
  llvm=no
  for f in /usr/lib/*/libLLVM-1[6-9]*.so* /usr/lib/*/libLLVM.so.1[6-9]* \
    /usr/lib/*/libLLVM-[2-9][0-9]*.so* /usr/lib/*/libLLVM.so.[2-9][0-9]*; do
    [ -e "$f" ] && llvm=yes
  done
  [ "$llvm" = yes ] || missing+=(libllvm19)
fi
if [ "${GARTOWEN_SKIP_PROOFS:-0}" != 1 ] && ls proofs/*.v >/dev/null 2>&1; then
  if have coqc; then
    probe=$(mktemp -d)
    printf 'From Flocq Require Import Core.\n' >"$probe/probe.v"
    (cd "$probe" && coqc probe.v >/dev/null 2>&1) || missing+=(libcoq-flocq)
    rm -rf "$probe"
  else
    missing+=(coq libcoq-flocq)
  fi
  have ocamlopt || missing+=(ocaml-nox)
fi
# Only what is missing and required is installed, and the script says so first: nothing
# optional (GNU parallel, which examples/ci/shard-local.sh uses when present, falls back to
# xargs -P), nothing for the parts a command skips. GARTOWEN_NO_INSTALL=1 never installs.
[ ${#missing[@]} -eq 0 ] && exit 0
line="apt-get install -y ${missing[*]}"
if [ "${GARTOWEN_NO_INSTALL:-0}" != 1 ] && [ "$(id -u)" = 0 ] && have apt-get; then
  echo "prerequisites: ${missing[*]} missing and required; installing them as root with" \
    "'$line' (GARTOWEN_NO_INSTALL=1 stops instead)"
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive $line -qq && exit 0
  echo "prerequisites: apt-get failed" >&2
fi
echo "prerequisites: missing ${missing[*]}. Install them first (Debian/Ubuntu):" >&2
echo "    sudo $line" >&2
echo "or set GARTOWEN_SKIP_PROOFS=1 to run without the Coq proofs (they are then not checked)." >&2
exit 1
