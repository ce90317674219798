#!/usr/bin/env bash
# Runs `gartowen verify` as N shards in parallel on one machine (GNU parallel; xargs -P when it
# is missing), then merges the shard certificates into one. The merge equals an unsharded
# run's certificate up to the `seconds` fields (a CI job matrix does the same across machines).
#
# Usage: shard-local.sh N OUT_DIR [verify options...]
#   GARTOWEN=path/to/gartowen examples/ci/shard-local.sh 4 shards --level quick
# Exit codes: those of `gartowen verify` (0 pass, 1 a check failed, 2 bad usage, 3 external
# program failed); a shard that exits 2 or 3 stops the merge.
set -euo pipefail
g="${GARTOWEN:-gartowen}"
n="${1:?usage: shard-local.sh N OUT_DIR [verify options...]}"
out="${2:?usage: shard-local.sh N OUT_DIR [verify options...]}"
shift 2
mkdir -p "$out"
run_shard() { # I N OUT G ARGS...: one shard; its exit code goes to OUT/shardI.rc
  local i="$1" n="$2" out="$3" g="$4"
  shift 4
  set +e
  "$g" verify --shard "$i/$n" --json "$out/shard$i.json" "$@" > "$out/shard$i.txt" 2>&1
  echo $? > "$out/shard$i.rc"
}
export -f run_shard
if command -v parallel > /dev/null; then
  seq 1 "$n" | parallel --will-cite run_shard {} "$n" "$out" "$g" "$@"
else
  seq 1 "$n" | xargs -P "$n" -I{} bash -c 'run_shard "$@"' _ {} "$n" "$out" "$g" "$@"
fi
worst=0
for i in $(seq 1 "$n"); do
  rc=$(cat "$out/shard$i.rc")
  if [ "$rc" -ge 2 ]; then
    echo "shard $i/$n failed to run (exit $rc):" >&2
    cat "$out/shard$i.txt" >&2
    exit "$rc"
  fi
  [ "$rc" -gt "$worst" ] && worst=$rc
done
shards=()
for i in $(seq 1 "$n"); do shards+=("$out/shard$i.json"); done
"$g" verify --merge "${shards[@]}" --json "$out/merged.json" > "$out/merged.txt"
cat "$out/merged.txt"
exit "$worst"
