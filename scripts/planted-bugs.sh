#!/usr/bin/env bash
# Seeds each bug of tests/planted/*.patch into the Rust checker, runs the differential tests
# of the counting checker against its Coq model (the small corpus, tests/extracted_checker.rs,
# and the large one, tests/extracted_checker_large.rs, with its large-tier sets) and reports
# which test sees it. Exits 0 when every planted bug fails at least one of them, 1 when one
# goes unseen. The working tree is restored after each (and on interruption). Needs coqc and
# ocamlopt; a few minutes each.
# Usage: scripts/planted-bugs.sh [PATCH...]
set -euo pipefail
cd "$(dirname "$0")/.."
patches=("$@")
[ ${#patches[@]} -gt 0 ] || patches=(tests/planted/*.patch)
current=""
restore() { [ -n "$current" ] && git apply -R "$current" && current=""; }
trap restore EXIT INT TERM
unseen=0
for p in "${patches[@]}"; do
  git apply --check "$p" || { echo "planted-bugs: $p does not apply to this tree" >&2; exit 2; }
  git apply "$p"; current="$p"
  verdicts=""
  # The agreement tests only: extracted_checker_large's check that the patches apply fails
  # while one is applied (its line is gone), which would count that bug as seen.
  for t in extracted_checker::the_rust extracted_checker_large::the_net_checker; do
    if cargo test -q --test integration "$t" -- --include-ignored >/dev/null 2>&1; then
      verdicts+=" $t passed (unseen);"
    else
      verdicts+=" $t FAILED (seen);"
    fi
  done
  restore
  echo "planted-bugs: $(basename "$p" .patch):$verdicts"
  case "$verdicts" in *FAILED*) ;; *) unseen=1 ;; esac
done
exit "$unseen"
