#!/usr/bin/env bash
# Runs both CI examples, every job and step in order, in clean clones (run-locally.py), with a
# user repository made for the purpose: src/my_scrambler.c is examples/external/lk_hash.c and
# gartowen is the submodule vendor/gartowen (this repository's HEAD). Then checks that:
# - the quick `verify` job fails for the right reason: lk-hash claims Owen in the example but is
#   not one (the JUnit names pair-law); so the gate works on the user's program;
# - every exhaustive shard and the merge pass, and the merged certificate covers every 32-bit
#   word of the swept dimensions of the user's program (external) in 4 pieces, with its JUnit:
#   dimension 0 for GitHub, as written; the GitLab pipeline (dimensions 0..1 by default) runs
#   with SWEEP_DIMS=0..0 given as a pipeline variable (half the time, and the override path
#   checked);
# - the GitHub merge job without its checkout step fails ("not a directory"), as does the
#   GitLab pipeline without submodules: a missing checkout or path fails here, not in the
#   user's pipeline.
# Usage: test-examples.sh GARTOWEN_BINARY [WORK_DIR]   (about a minute and a half per example on 2 cores)
# Needs git, cc, python3 with PyYAML. Exit 0 all as expected, 1 otherwise (named).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
g="$(cd "$(dirname "${1:?usage: test-examples.sh GARTOWEN_BINARY [WORK_DIR]}")" && pwd)/$(basename "$1")"
work="${2:-$(mktemp -d)}"
mkdir -p "$work"; work="$(cd "$work" && pwd)"
py="${PYTHON:-python3}"
"$py" -c "import yaml" 2>/dev/null || { echo "test-examples.sh: $py lacks PyYAML (pip install pyyaml; Debian: apt-get install python3-yaml)" >&2; exit 1; }
fail=0
bad() { echo "FAILED: $*" >&2; fail=1; }

user="$work/user-repo"
mkdir -p "$user/src"
cp "$repo/examples/external/lk_hash.c" "$user/src/my_scrambler.c"
cp "$repo/examples/external/protocol.h" "$user/src/"
git -C "$user" init -q
git -C "$user" -c protocol.file.allow=always submodule add -q "$repo" vendor/gartowen
git -C "$user" add -A
git -C "$user" -c user.name=test -c user.email=test@example.invalid commit -q -m "a user's repository"

run() { # KIND PIPELINE WORK [run-locally options]: its exit code, its status lines in WORK.status
  local kind="$1" pipeline="$2" dir="$3"
  shift 3
  set +e
  "$py" "$here/run-locally.py" "$kind" "$pipeline" "$user" --gartowen "$g" --work "$dir" "$@" \
    > "$dir.status" 2> "$dir.err"
  local rc=$?
  set -e
  return "$rc"
}
expect_status() { # FILE STATUS JOB
  grep -q -x -E "$2 +$3" "$1" || bad "$(basename "$1"): job '$3' is not $2: $(tr '\n' ';' < "$1")"
}
merged_ok() { # CERTIFICATE JUNIT LAST_DIMENSION
  "$py" - "$1" "$2" "$3" <<'PY' || fail=1
import json, re, sys, xml.etree.ElementTree as ET
cert = json.load(open(sys.argv[1]))
text = json.dumps(cert)
assert cert["verdict"] == "pass", f"merged verdict {cert['verdict']}"
assert "external" in text and "my_scrambler" in text, "the merged certificate is not about the user's program"
cases = list(ET.parse(sys.argv[2]).getroot().iter("testcase"))
assert len(cases) == 4 and not any(c.find("failure") is not None for c in cases), "JUnit: 4 passing dimension pieces expected"
# The pieces tile dimensions 0 to the last swept, each from its first chunk to its last.
dims = list(range(int(sys.argv[3]) + 1))
pieces = {}
for c in cases:
    dim, start, end = map(int, re.fullmatch(r"dim (\d+) chunks (\d+)\.\.(\d+)", c.get("name")).groups())
    pieces.setdefault(dim, []).append((start, end))
assert sorted(pieces) == dims, f"dimensions {sorted(pieces)}, not {dims}"
# Every word: a 32-bit dimension is swept in 2^12 chunks (its 12-bit prefixes).
last = 1 << 12
for dim, runs in pieces.items():
    runs.sort()
    assert runs[0][0] == 0 and all(a[1] == b[0] for a, b in zip(runs, runs[1:])), f"dim {dim}: {runs}"
    assert runs[-1][1] == last, f"dim {dim} stops early: {runs}"
print(f"merged: pass, dimensions 0..{dims[-1]} in 4 pieces, {sys.argv[1]}")
PY
}

for kind in github gitlab; do
  pipeline="$here/$([ $kind = github ] && echo github-actions.yml || echo gitlab-ci.yml)"
  if [ $kind = github ]; then override=(); else override=(--variable SWEEP_DIMS=0..0); fi
  last_dim=0
  rc=0; run "$kind" "$pipeline" "$work/$kind" "${override[@]}" || rc=$?
  [ "$rc" = 1 ] || bad "$kind: run-locally exited $rc, not 1 (the verify job fails): $(cat "$work/$kind.err")"
  expect_status "$work/$kind.status" failed verify
  grep -q 'FAIL pair-law' "$work/$kind/log.txt" || bad "$kind: the verify job did not fail on pair-law"
  grep -q 'failure' "$work/$kind/artifacts/"*/verify.xml || bad "$kind: verify.xml records no failure"
  expect_status "$work/$kind.status" passed exhaustive
  expect_status "$work/$kind.status" passed merge
  merged_ok "$(ls "$work/$kind/artifacts/"*/exhaustive.json)" "$(ls "$work/$kind/artifacts/"*/exhaustive.xml)" "$last_dim"
done

# The GitHub merge job without its checkout: fails at the install step, named.
"$py" - "$here/github-actions.yml" "$work/no-checkout.yml" <<'PY'
import sys, yaml
doc = yaml.safe_load(open(sys.argv[1]))
steps = doc["jobs"]["merge"]["steps"]
doc["jobs"]["merge"]["steps"] = [s for s in steps if not str(s.get("uses", "")).startswith("actions/checkout")]
assert len(doc["jobs"]["merge"]["steps"]) == len(steps) - 1
yaml.safe_dump(doc, open(sys.argv[2], "w"), sort_keys=False)
PY
rc=0; run github "$work/no-checkout.yml" "$work/no-checkout" --only merge --artifacts-from "$work/github/artifacts" || rc=$?
[ "$rc" = 1 ] || bad "github without the merge checkout: exit $rc, not 1"
expect_status "$work/no-checkout.status" failed merge
grep -q "is not a directory" "$work/no-checkout/log.txt" || bad "github without the merge checkout: no 'not a directory'"

# The GitLab pipeline without submodules: vendor/gartowen is empty, the install fails.
sed '/GIT_SUBMODULE_STRATEGY/d' "$here/gitlab-ci.yml" > "$work/no-submodule.yml"
rc=0; run gitlab "$work/no-submodule.yml" "$work/no-submodule" --only merge --artifacts-from "$work/gitlab/artifacts" || rc=$?
[ "$rc" = 1 ] || bad "gitlab without submodules: exit $rc, not 1"
expect_status "$work/no-submodule.status" failed merge

[ "$fail" = 0 ] && echo "test-examples.sh: both CI examples run as expected ($work)"
exit "$fail"
