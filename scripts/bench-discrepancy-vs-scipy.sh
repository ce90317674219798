#!/usr/bin/env bash
# Speed against error, gartowen beside scipy.stats.qmc.discrepancy in the same run.
# Installs scipy from PyPI if missing (benchmarks may; tests never use Python).
set -euo pipefail
cd "$(dirname "$0")/.."
python3 -c "import scipy" 2>/dev/null || python3 -m pip install -q scipy numpy
dir=$(mktemp -d)
cargo run --release -q -p gartowen-discrepancy --example speed_vs_error "$dir" | tee "$dir/gartowen.md"
python3 - "$dir" <<'PY'
import sys, time, glob, re, numpy as np
from scipy.stats import qmc
d = sys.argv[1]
exact = {}
for line in open(f"{d}/gartowen.md"):
    m = re.match(r"<!-- (\w+) (\d+) (\d+) exact (\S+) -->", line)
    if m: exact[(m[1], int(m[2]), int(m[3]))] = float(m[4])
print("| kind | N | d | scipy method | seconds | rel. error vs exact |")
print("|---|---|---|---|---|---|")
for f in sorted(glob.glob(f"{d}/*.f64")):
    n, dim = map(int, re.findall(r"n(\d+)_d(\d+)", f)[0])
    x = np.fromfile(f, dtype="<f8").reshape(n, dim)
    if n > 1 << 16: continue
    for kind, method, square in [("l2star", "L2-star", True), ("cd", "CD", False)]:
        if dim != 2 and kind == "cd": continue
        for workers in (1, 2):
            t = time.perf_counter(); v = qmc.discrepancy(x, method=method, workers=workers); s = time.perf_counter() - t
            v = v * v if square else v   # scipy returns the root for L2-star
            e = exact.get((kind, n, dim))
            err = f"{abs(v - e) / e:.1e}" if e else "n/a"
            print(f"| {kind} | {n} | {dim} | scipy workers={workers} | {s:.4f} | {err} |")
PY
