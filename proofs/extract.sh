#!/usr/bin/env bash
# Builds the differential driver and the witness re-checker from the Coq extraction: compiles
# the theories the extraction needs, runs Extract.v in OUT (it writes gartowen_extracted.ml
# there) and compiles extracted/driver.ml and extracted/revalidate.ml against it with ocamlopt
# into OUT/driver and OUT/revalidate.
# Usage: proofs/extract.sh OUT    (tests/extracted_differential.rs calls it with target/extracted)
# Nothing is rebuilt when OUT's build is newer than every theory, driver source and this script,
# and concurrent calls (one per test process under cargo-nextest) wait for one build: OUT holds
# a lock while it builds.
set -euo pipefail
proofs="$(cd "$(dirname "$0")" && pwd)"
out="${1:?usage: proofs/extract.sh OUT}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
exec 9>"$out/.lock"
flock 9
stamp="$out/.built"
if [ -f "$stamp" ] && [ -x "$out/driver" ] && [ -x "$out/revalidate" ] &&
  [ -z "$(find "$proofs" -maxdepth 2 \( -name '*.v' -o -name '*.ml' -o -name extract.sh \) -newer "$stamp")" ]; then
  exit 0
fi
rm -f "$stamp"
for tool in coqc ocamlopt; do
  command -v "$tool" >/dev/null || { echo "extract: $tool is missing (Debian's coq brings both)" >&2; exit 1; }
done
for t in Nested Boxes ScanMap Checker Art ArtWord Laws Symmetric NetMonotone Witness NodeLaws ArtMarginal Rank RankBasis; do
  coqc -Q "$proofs" Gartowen "$proofs/$t.v"
done
cd "$out"
coqc -Q "$proofs" Gartowen "$proofs/Extract.v"
cp "$proofs/extracted/driver.ml" .
cp "$proofs/extracted/revalidate.ml" .
ocamlopt -w -a gartowen_extracted.mli gartowen_extracted.ml driver.ml -o driver
ocamlopt -w -a gartowen_extracted.mli gartowen_extracted.ml revalidate.ml -o revalidate
touch "$stamp"
