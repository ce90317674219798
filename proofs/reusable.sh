#!/usr/bin/env bash
# Prints the theories among THEORY... (in dependency order) whose compiled .vo in DIR can be
# reused instead of compiling them again, by make's rule: the .vo is newer than every .v in DIR
# (so it was compiled from these sources) and every Gartowen theory it requires is reused too
# (so the libraries it was compiled against are the ones the others load).
# Usage: proofs/reusable.sh DIR THEORY...   (proofs/check.sh reuses what proofs/extract.sh built)
set -euo pipefail
dir="${1:?usage: proofs/reusable.sh DIR THEORY...}"
shift
cd "$dir"
newest_source=$(ls -t ./*.v | head -1)
declare -A reused=()
for t in "$@"; do
  [ -f "$t.vo" ] && [ "$t.vo" -nt "$newest_source" ] || continue
  all_reused=1
  for r in $(sed -n 's/^From Gartowen Require Import \(.*\)\./\1/p' "$t.v"); do
    [ -n "${reused[$r]:-}" ] || all_reused=0
  done
  if [ "$all_reused" = 1 ]; then
    reused[$t]=1
    echo "$t"
  fi
done
