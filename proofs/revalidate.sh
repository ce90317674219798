#!/usr/bin/env bash
# Re-checks a witness of `gartowen check --witness FILE` with the checker extracted from the
# Coq proofs (Witness.v): builds it into target/extracted with proofs/extract.sh when it is
# missing or older than the theories, then runs it. Exit 0: the claim is re-checked; 1: the
# re-check rejects it; 2: the file is malformed or outside the re-checked range.
# Usage: proofs/revalidate.sh WITNESS_FILE
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
[ $# -eq 1 ] || { echo "usage: proofs/revalidate.sh WITNESS_FILE" >&2; exit 2; }
[ -r "$1" ] || { echo "revalidate: cannot read $1" >&2; exit 2; }
bin="$root/target/extracted/revalidate"
stale=0
[ -x "$bin" ] || stale=1
if [ "$stale" = 0 ]; then
  for f in "$root"/proofs/*.v "$root"/proofs/extracted/revalidate.ml; do
    [ "$f" -nt "$bin" ] && stale=1 && break
  done
fi
if [ "$stale" = 1 ]; then
  echo "revalidate: building the extracted checker (proofs/extract.sh, about a minute)" >&2
  "$root/proofs/extract.sh" "$root/target/extracted" >/dev/null
fi
# The extracted list functions recurse once per point: give them the stack they need.
ulimit -s unlimited 2>/dev/null || ulimit -s "$(ulimit -H -s)" 2>/dev/null || true
exec "$bin" "$1"
