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
# The theories proofs/extract.sh compiled here for the Rust tests are not compiled twice:
# reusable.sh names those whose .vo is newer than every source and requires only reused ones.
# A .vo being written beside this run would fail to load, never pass unchecked.
# GARTOWEN_PROOFS_FRESH=1 compiles every theory.
declare -A reused=()
if [ "${GARTOWEN_PROOFS_FRESH:-0}" != 1 ]; then
  for t in $(./reusable.sh . "${theories[@]}"); do
    cp "$t.vo" "$build"/
    reused[$t]=1
  done
fi
cd "$build"
for t in "${theories[@]}"; do
  if [ -n "${reused[$t]:-}" ]; then
    echo "proofs: $t.v reused: its .vo in proofs/ is newer than every source"
  else
    coqc -Q . Gartowen "$t.v"
    echo "proofs: $t.v compiled"
  fi
done
# The assumption listings. One `Print Assumptions` walks everything its theorem depends on, and
# the theorems share most of it, so each list is checked as one tuple of all its theorems (a
# few seconds, where one command per theorem took 35-50 s): the tuple rests on exactly the union
# of their axioms. Only when that is not as required does the per-theorem file run, to name the
# theorem.
names_of() { grep '^Print Assumptions' "$1" | awk '{print $3}' | tr -d .; }
# tuple FILE OUT: OUT.v prints the assumptions of the tuple of FILE's listed theorems.
tuple() {
  {
    grep '^From ' "$1"
    printf 'Definition gartowen_listed_theorems := (%s).\n' \
      "$(names_of "$1" | sed 's/^/@/' | paste -sd, - | sed 's/,/, /g')"
    echo 'Print Assumptions gartowen_listed_theorems.'
  } > "$2.v"
}
# per_theorem FILE: runs FILE's commands one theorem at a time and prints each theorem's axioms
# (block K of coqc's output belongs to the K-th listed theorem). Slow: only to name a failure.
per_theorem() {
  coqc -Q . Gartowen "$1" 2>&1 | awk '
    /^Axioms:/ || /^Closed under the global context/ {
      if (k) print k, list; k++; list = ""
      if ($0 ~ /^Closed/) list = " closed"
      next
    }
    /^[A-Za-z_][A-Za-z0-9_.]*( :|$)/ { list = list " " $1 }
    END { if (k) print k, list }' |
    while read -r k axioms; do
      echo "proofs: $(names_of "$1" | sed -n "${k}p"): $axioms"
    done
}
tuple AssumptionsFloat.v FloatTuple
coqc -Q . Gartowen FloatTuple.v > float.out 2>&1 &
float_pid=$!
tuple Assumptions.v MainTuple
expected=$(names_of Assumptions.v | wc -l)
if ! out=$(coqc -Q . Gartowen MainTuple.v 2>&1) || [ "$out" != "Closed under the global context" ]; then
  printf '%s\n' "$out" | sed 's/^/proofs: /'
  per_theorem Assumptions.v | grep -v ': closed$' >&2
  echo "proofs: not every one of the $expected main theorems of Assumptions.v is closed under the global context" >&2
  exit 1
fi
names_of Assumptions.v | while read -r name; do echo "proofs: $name: Closed under the global context"; done
echo "proofs: all $expected main theorems closed under the global context"

# Floating point: the theorems' axioms together are among the allowed ones, listed by name.
if ! wait "$float_pid"; then
  sed 's/^/proofs: /' float.out >&2
  echo "proofs: AssumptionsFloat.v's theorems do not compile as a tuple" >&2
  exit 1
fi
out=$(cat float.out)
case "$(printf '%s\n' "$out" | head -1)" in
  Axioms:|"Closed under the global context") ;;
  *) printf '%s\n' "$out" | sed 's/^/proofs: /'; echo "proofs: no axiom list for AssumptionsFloat.v" >&2; exit 1 ;;
esac
used=$(printf '%s\n' "$out" | grep -E '^[A-Za-z_][A-Za-z0-9_.]* *$|^[A-Za-z_][A-Za-z0-9_.]* :' | grep -v '^Axioms:' | awk '{print $1}' | sort -u)
for a in $used; do
  ok=0
  for b in "${allowed_axioms[@]}"; do [ "$a" = "$b" ] && ok=1; done
  if [ "$ok" != 1 ]; then
    per_theorem AssumptionsFloat.v | grep -F " $a" >&2
    echo "proofs: the theorems above rest on $a, which is not a standard axiom of the reals" >&2
    exit 1
  fi
done
float_count=$(names_of AssumptionsFloat.v | wc -l)
echo "proofs: the $float_count floating-point theorems of AssumptionsFloat.v rest only on standard axioms of the reals:" $used
names_of AssumptionsFloat.v | paste -sd' ' - | fold -s -w 96 | sed 's/^/proofs:   /'
