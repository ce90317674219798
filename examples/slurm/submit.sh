#!/usr/bin/env bash
# Submits a gartowen job array and the dependent job that joins it, in one command.
#
# Usage: submit.sh [--wait] verify N OUT [verify options...]
#        submit.sh [--wait] check LIST OUT
#   GARTOWEN=$PWD/target/release/gartowen examples/slurm/submit.sh verify 32 out \
#       --level exhaustive --dims 0..1023 --impl art-owen-2
#   examples/slurm/submit.sh --wait verify 4 out --level exhaustive --dims 0..3 \
#       --external ./my_scrambler --base 2 --claim nested
# verify: an array of N shards (verify-array.sbatch), then merge.sbatch → OUT/merged.json and
# OUT/merged.xml. check: one task per line of LIST (check-array.sbatch), then
# check-summary.sbatch → OUT/summary.txt. Task logs go to OUT/logs/. OUT, the program and
# GARTOWEN must be on a file system every node sees. Extra sbatch options (partition, account,
# --time for long shards) go in SBATCH_* variables, e.g. SBATCH_PARTITION=short; options for
# the array tasks alone in GARTOWEN_ARRAY_OPTS, e.g. "--cpus-per-task=8 --time=04:00:00".
# Prints the two job ids. With --wait it returns when the joining job has ended, with its exit
# code (0 pass, 1 a check failed, 2 a shard or check missing or refused, or sbatch refused the
# array).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
wait=0
if [ "${1:-}" = --wait ]; then wait=1; shift; fi
usage="usage: submit.sh [--wait] verify N OUT [verify options...] | submit.sh [--wait] check LIST OUT"
kind="${1:?$usage}"
command -v sbatch >/dev/null || { echo "submit.sh: sbatch not found: is this a Slurm login node?" >&2; exit 2; }
# submit_pair TASKS NAME ARRAY_SCRIPT JOIN_SCRIPT JOIN_LOG ARRAY_ARGS... -- JOIN_ARGS...:
# the array of TASKS tasks (logs OUT/logs/NAME-K.out), then the joining job after every task
# has ended; the exit code is sbatch's (with --wait, the joining job's).
# A path as a Slurm --output pattern: a literal % is written %%, so that an OUT with % in
# its name is not read as a pattern (%j, %a, …).
pattern() { printf '%s' "${1//%/%%}"; }
submit_pair() {
  local tasks="$1" name="$2" array_script="$3" join_script="$4" join_log="$5"
  shift 5
  local array_args=()
  while [ "$1" != -- ]; do array_args+=("$1"); shift; done
  shift
  local array
  array=$(sbatch --parsable --array="1-$tasks" ${GARTOWEN_ARRAY_OPTS:-} \
    --output="$(pattern "$out/logs/$name")-%a.out" "$here/$array_script" "${array_args[@]}") ||
    { echo "submit.sh: sbatch did not take the array (its message is above)" >&2; return 2; }
  array="${array%%;*}"
  echo "array $array: $tasks $name task(s); $join_script after it:" >&2
  local join
  join=$(sbatch --parsable --dependency="afterany:$array" --kill-on-invalid-dep=yes \
    --output="$(pattern "$out/logs/$join_log")" "$here/$join_script" "$@") ||
    { echo "submit.sh: sbatch did not take the joining job (its message is above)" >&2; return 2; }
  join="${join%%;*}"
  echo "$join"
  [ "$wait" = 1 ] || return 0
  wait_for "$join"
}
# wait_for JOB: returns JOB's exit code once it has ended (2 when it was cancelled, killed by a
# signal or its record is gone). Polled every second: `sbatch --wait` doubles its polling
# interval up to 32 s, which made a 10-second array wait half a minute more.
wait_for() {
  local info state code
  while :; do
    info=$(scontrol show job -o "$1" 2>&1) ||
      { echo "submit.sh: job $1 is no longer known to Slurm: $info" >&2; return 2; }
    state=$(sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' <<<"$info")
    case "$state" in
      PENDING|RUNNING|CONFIGURING|COMPLETING|SUSPENDED|REQUEUED|RESIZING|"") sleep 1 ;;
      *)
        code=$(sed -n 's/.*ExitCode=\([0-9]*\):\([0-9]*\).*/\1 \2/p' <<<"$info")
        case "$state $code" in
          "COMPLETED "*|"FAILED "*" 0") return "${code%% *}" ;;
          *) echo "submit.sh: job $1 ended $state (exit code ${code:-unknown})" >&2; return 2 ;;
        esac
        ;;
    esac
  done
}

case "$kind" in
  verify)
    n="${2:?$usage}"; out="${3:?$usage}"; shift 3
    [[ "$n" =~ ^[1-9][0-9]*$ ]] || { echo "submit.sh: N must be a positive integer, not '$n'" >&2; exit 2; }
    mkdir -p "$out/logs"; out="$(cd "$out" && pwd)"
    rc=0
    submit_pair "$n" verify verify-array.sbatch merge.sbatch merge.out "$out" "$@" -- "$out" "$n" || rc=$?
    ;;
  check)
    list="${2:?$usage}"; out="${3:?$usage}"
    [ -f "$list" ] || { echo "submit.sh: no list file '$list'" >&2; exit 2; }
    k=$(grep -c -v -E '^[[:space:]]*(#|$)' "$list" || true)
    [ "$k" -gt 0 ] || { echo "submit.sh: '$list' has no checks" >&2; exit 2; }
    mkdir -p "$out/logs"; out="$(cd "$out" && pwd)"; list="$(cd "$(dirname "$list")" && pwd)/$(basename "$list")"
    rc=0
    submit_pair "$k" check check-array.sbatch check-summary.sbatch summary.out "$list" "$out" -- "$list" "$out" || rc=$?
    ;;
  *) echo "submit.sh: unknown kind '$kind' ($usage)" >&2; exit 2 ;;
esac
exit "$rc"
