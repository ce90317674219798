#!/usr/bin/env bash
# Checks the Coq proofs: compiles every theory, then requires `Print Assumptions` of each main
# theorem to report "Closed under the global context" and the sources to contain no Admitted,
# admit, Axiom or Parameter. Fails when coqc is missing, unless GARTOWEN_SKIP_PROOFS=1 asks to
# skip (then it says so loudly). Run from anywhere. It compiles a copy of the sources in a
# temporary folder, so it can run while proofs/extract.sh (the Rust tests) builds in proofs/.
set -euo pipefail
cd "$(dirname "$0")"
theories=(Nested Boxes ScanMap Checker Factor Counterexample Art ArtWord Binary Laws Symmetric NetMonotone Witness ArtPair NodeLaws ArtMarginal Affine Rank RankBasis NetRank GLTransitive Float DdSum Discrepancy WrapAround)
# The only axioms a floating-point theorem may rest on: Coq's classical reals, which Flocq uses.
allowed_axioms=(ClassicalDedekindReals.sig_forall_dec ClassicalDedekindReals.sig_not_dec
  FunctionalExtensionality.functional_extensionality_dep Classical_Prop.classic)

if ! command -v coqc >/dev/null 2>&1; then
  if [ "${GARTOWEN_SKIP_PROOFS:-0}" = 1 ]; then
    echo "######## WARNING: coqc not found and GARTOWEN_SKIP_PROOFS=1: the proofs were NOT checked ########"
    exit 0
  fi
  echo "proofs: coqc is missing (install Debian's coq package, or set GARTOWEN_SKIP_PROOFS=1 to skip loudly)" >&2
  exit 1
fi

if grep -nE '\b(Admitted|admit|Axiom|Parameter|Conjecture)\b' ./*.v; then
  echo "proofs: the lines above admit or assume something" >&2
  exit 1
fi

echo "proofs: $(coqc --version | head -1)"
if ! printf 'From Flocq Require Import Core.\n' > /tmp/gartowen_flocq_probe.v ||
   ! coqc /tmp/gartowen_flocq_probe.v >/dev/null 2>&1; then
  echo "proofs: Flocq is missing (install Debian's libcoq-flocq)" >&2
  exit 1
fi
build=$(mktemp -d "${TMPDIR:-/tmp}/gartowen-proofs.XXXXXX")
trap 'rm -rf "$build"' EXIT
cp ./*.v "$build"/
cd "$build"
for t in "${theories[@]}"; do
  coqc -Q . Gartowen "$t.v"
  echo "proofs: $t.v compiled"
done
# The two assumption listings need only the theories: the floating-point one runs beside.
coqc -Q . Gartowen AssumptionsFloat.v > float.out 2>&1 &
float_pid=$!
out=$(coqc -Q . Gartowen Assumptions.v)
expected=$(grep -c '^Print Assumptions' Assumptions.v)
closed=$(printf '%s\n' "$out" | grep -c 'Closed under the global context' || true)
if [ "$closed" = "$expected" ]; then
  grep '^Print Assumptions' Assumptions.v | awk '{print $3}' | tr -d . |
    while read -r name; do echo "proofs: $name: Closed under the global context"; done
else
  printf '%s\n' "$out" | sed 's/^/proofs: /'
fi
if [ "$closed" != "$expected" ]; then
  echo "proofs: only $closed of $expected main theorems are closed under the global context" >&2
  exit 1
fi
echo "proofs: all $expected main theorems closed under the global context"

# Floating point: every theorem's axioms are among the allowed ones, each listed by name.
if ! wait "$float_pid"; then
  sed 's/^/proofs: /' float.out >&2
  echo "proofs: AssumptionsFloat.v failed" >&2
  exit 1
fi
out=$(cat float.out)
expected=$(grep -c '^Print Assumptions' AssumptionsFloat.v)
blocks=$(printf '%s\n' "$out" | grep -c '^Axioms:' || true)
if [ "$blocks" != "$expected" ]; then
  printf '%s\n' "$out" | sed 's/^/proofs: /'
  echo "proofs: expected $expected axiom lists from AssumptionsFloat.v, found $blocks" >&2
  exit 1
fi
used=$(printf '%s\n' "$out" | grep -E '^[A-Za-z_][A-Za-z0-9_.]* *$|^[A-Za-z_][A-Za-z0-9_.]* :' | grep -v '^Axioms:' | awk '{print $1}' | sort -u)
for a in $used; do
  ok=0
  for b in "${allowed_axioms[@]}"; do [ "$a" = "$b" ] && ok=1; done
  if [ "$ok" != 1 ]; then
    echo "proofs: a floating-point theorem rests on $a, which is not a standard axiom of the reals" >&2
    exit 1
  fi
done
# Each theorem with its own axioms (block K of the output belongs to the K-th Print).
names=$(grep '^Print Assumptions' AssumptionsFloat.v | awk '{print $3}' | tr -d .)
printf '%s\n' "$out" | awk '
  /^Axioms:/ || /^Closed under the global context/ {
    if (k) print k, list; k++; list = ""
    if ($0 ~ /^Closed/) list = " (none)"
    next
  }
  /^[A-Za-z_][A-Za-z0-9_.]*( :|$)/ { list = list " " $1 }
  END { if (k) print k, list }' |
  while read -r k axioms; do
    echo "proofs: $(printf '%s\n' "$names" | sed -n "${k}p"): only standard axioms of the reals:$([ -n "$axioms" ] && echo " $axioms")"
  done
