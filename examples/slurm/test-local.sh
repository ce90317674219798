#!/usr/bin/env bash
# Exercises the job-array scripts beside it on a real Slurm: starts a single-node cluster on
# localhost (local-cluster.sh), submits a 4-task and a 1-task exhaustive verify array with their
# merges, and a check array with its summary, and compares what they wrote with unsharded runs
# of the same commands: each merged certificate must equal the unsharded one (timings and
# digest aside), each check certificate its unsharded twin, and the summary must name the
# violated check.
#
# Usage: test-local.sh GARTOWEN_BINARY [WORK_DIR]
# Exit: 0 all equal; 1 a difference (shown); 77 Slurm cannot run here (not root, or the
# packages are missing and apt-get is not available), said on stderr.
# As root with apt-get, installs slurmctld slurmd slurm-client munge when missing (seconds).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
g="$(cd "$(dirname "${1:?usage: test-local.sh GARTOWEN_BINARY [WORK_DIR]}")" && pwd)/$(basename "$1")"
if [ -n "${2:-}" ]; then
  mkdir -p "$2"; work="$(cd "$2" && pwd)"
else
  work="$(mktemp -d)"
  chmod 755 "$work" # the daemons' users (munge) must reach the cluster folder inside it
fi
[ -x "$g" ] || { echo "test-local.sh: '$1' is not an executable gartowen" >&2; exit 2; }

packages="slurmctld slurmd slurm-client munge"
missing=0
for tool in munged slurmctld slurmd sbatch; do
  command -v "$tool" >/dev/null || [ -x "/usr/sbin/$tool" ] || missing=1
done
if [ "$(id -u)" != 0 ]; then
  echo "test-local.sh: SKIPPED: a local Slurm needs root (slurmd starts jobs as their owner)" >&2
  exit 77
fi
if [ "$missing" = 1 ]; then
  if command -v apt-get >/dev/null; then
    echo "test-local.sh: installing $packages"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $packages >/dev/null ||
      { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $packages >/dev/null; } ||
      { echo "test-local.sh: SKIPPED: apt-get install $packages failed" >&2; exit 77; }
  else
    echo "test-local.sh: SKIPPED: Slurm is missing; install: apt-get install $packages" >&2
    exit 77
  fi
fi

"$here/local-cluster.sh" up "$work/cluster" >/dev/null
trap '"$here/local-cluster.sh" down "$work/cluster"' EXIT
export SLURM_CONF="$work/cluster/slurm.conf"
export GARTOWEN="$g"
fail=0
# Certificates compared field by field, without wall-clock fields and the digest over them.
# The sweep's pieces record how the run was cut: adjacent pieces of one implementation and
# dimension with equal failures are joined first, so a sharded run that covers the same words
# with the same outcome compares equal to the unsharded one.
same() { # A B WHAT
  python3 - "$1" "$2" "$3" <<'PY' || fail=1
import json, sys
def joined(pieces):
    out = []
    for p in pieces:
        last = out[-1] if out else None
        if (last and (last["implementation"], last["dim"], last["failure"]) ==
                (p["implementation"], p["dim"], p["failure"]) and last["chunks"][1] == p["chunks"][0]):
            last["chunks"] = [last["chunks"][0], p["chunks"][1]]
            last["words"] += p["words"]
        else:
            out.append(dict(p))
    return out
def strip(v):
    if isinstance(v, dict):
        return {k: strip(joined(x) if k == "pieces" else x) for k, x in v.items()
                if k not in ("seconds", "digest")}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v
a, b, what = sys.argv[1:]
x, y = (strip(json.load(open(p))) for p in (a, b))
if x != y:
    print(f"DIFFERENT: {what}: {a} and {b}", file=sys.stderr)
    for k in sorted(set(x) | set(y)):
        if x.get(k) != y.get(k):
            print(f"  key {k!r}: {json.dumps(x.get(k))[:300]} vs {json.dumps(y.get(k))[:300]}", file=sys.stderr)
    sys.exit(1)
print(f"equal: {what}")
PY
}

# 1. verify: 4 array tasks over 2 dimensions of 2^32 words, so each task holds half a
# dimension (the README's 4 tasks over 4 dimensions cut at dimension seams only; halves also
# test the cuts inside one), merged after the array.
sweep=(--level exhaustive --dims 0..1 --impl lk-hash)
RAYON_NUM_THREADS=2 "$g" verify "${sweep[@]}" --json "$work/unsharded.json" > "$work/unsharded.txt"
set +e
"$here/submit.sh" --wait verify 4 "$work/verify" "${sweep[@]}" > "$work/verify-jobs.txt"
rc=$?
set -e
if [ "$rc" != 0 ]; then
  echo "FAILED: the merge job exited $rc" >&2; cat "$work/verify/logs/"*.out >&2; fail=1
fi
for i in 1 2 3 4; do
  grep -q "\"index\": $i" "$work/verify/shard$i.json" || { echo "FAILED: shard$i.json is not shard $i" >&2; fail=1; }
done
[ -f "$work/verify/merged.xml" ] || { echo "FAILED: no merged.xml" >&2; fail=1; }
same "$work/unsharded.json" "$work/verify/merged.json" "merged certificate of 4 array tasks = unsharded run"

# An array of one task is the whole run: its merge checks and keeps the certificate.
set +e
"$here/submit.sh" --wait verify 1 "$work/one" "${sweep[@]}" > "$work/one-jobs.txt"
rc=$?
set -e
[ "$rc" = 0 ] || { echo "FAILED: the merge of a 1-task array exited $rc" >&2; cat "$work/one/logs/"*.out >&2; fail=1; }
[ -f "$work/one/merged.xml" ] || { echo "FAILED: a 1-task array wrote no merged.xml" >&2; fail=1; }
same "$work/unsharded.json" "$work/one/merged.json" "certificate of a 1-task array = unsharded run"

# 2. check: one task per line; the second line is a 4-D Sobol net claimed at t = 0, violated.
"$g" generate --seq sobol --dims 4 --log2-n 10 --format npy -o "$work/sobol.npy"
"$g" generate --seq sz4 --dims 4 --log2-n 10 --format npy -o "$work/sz4.npy"
cat > "$work/checks.txt" <<LIST
# one gartowen check per line
$work/sz4.npy --base 4 --t 0
$work/sobol.npy --base 2 --t 0
$work/sobol.npy --base 2 --projections 0,1;0,2;1,2
LIST
set +e
"$here/submit.sh" --wait check "$work/checks.txt" "$work/check" > "$work/check-jobs.txt"
rc=$?
set -e
[ "$rc" = 1 ] || { echo "FAILED: the summary exited $rc, not 1 (one check violated)" >&2; fail=1; }
grep -q "^check 1: holds" "$work/check/summary.txt" &&
  grep -q "^check 2: VIOLATED" "$work/check/summary.txt" &&
  grep -q "^check 3: holds" "$work/check/summary.txt" ||
  { echo "FAILED: the summary does not read holds, VIOLATED, holds:" >&2; cat "$work/check/summary.txt" >&2; fail=1; }
k=0
while IFS= read -r line; do
  k=$((k + 1))
  read -r -a args <<< "$line"
  set +e
  "$g" check "${args[@]}" --json > "$work/unsharded-check$k.json"
  set -e
  same "$work/unsharded-check$k.json" "$work/check/check$k.json" "check $k as an array task = unsharded"
done < <(grep -v '^#' "$work/checks.txt")

[ "$fail" = 0 ] && echo "test-local.sh: the Slurm arrays agree with the unsharded runs ($work)"
exit "$fail"
