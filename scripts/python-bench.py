#!/usr/bin/env python3
"""Timings of the Python package against SciPy, measured in one run on this machine.

1. gartowen.discrepancy against scipy.stats.qmc.discrepancy (L2-star) on scrambled Sobol:
   2-D 2^16 points and 16-D 2^14 points, with each one's relative error against the exact
   value (gartowen's exact rational method; 2-D through the O(N log N) exact path).
2. gartowen.verify on a NumPy per-bit Owen scramble (python/tests/scramblers.py), many seeds
   per call (batch_seeds=True) and one seed per call, each split into the time inside the
   Python function and the rest, against the same battery on its built-in twin
   `owen-per-bit-hash` (`gartowen verify --level quick --impl owen-per-bit-hash`, release).

Run: target/pyvenv/bin/python scripts/python-bench.py target/release/gartowen
(after scripts/python-tests.sh and cargo build --release -p gartowen-cli)
"""

import json
import sys
import time
from fractions import Fraction

import numpy as np
from scipy.stats import qmc

import gartowen


def best_of(repeats, fn):
    best, out = float("inf"), None
    for _ in range(repeats):
        t = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t)
    return best, out


def rel(value, exact):
    return float(abs(Fraction(value) - exact) / exact)


def discrepancy_rows():
    rows = []
    for dims, m, repeats in [(2, 16, 1), (16, 14, 1)]:
        x = gartowen.generate("sobol", dims, 1 << m, scramble="owen-oracle", seed=1)
        ours_t, ours = best_of(3, lambda: gartowen.discrepancy(x, "l2star"))
        scipy_t, theirs = best_of(repeats, lambda: qmc.discrepancy(x, method="L2-star"))
        exact = gartowen.discrepancy(x, "l2star", "exact" if dims > 2 else "fast").exact
        rows.append({
            "points": f"{dims}-D 2^{m}",
            "gartowen_s": ours_t,
            "gartowen_method": ours.method,
            "scipy_s": scipy_t,
            "speedup": scipy_t / ours_t,
            # SciPy returns D for L2-star: compare squares.
            "gartowen_rel_error": rel(ours.value, exact),
            "gartowen_bound": ours.rel_error_bound,
            "scipy_rel_error": rel(theirs * theirs, exact),
        })
    return rows


def verify_split(batch_seeds):
    sys.path.insert(0, "python/tests")
    from scramblers import owen_per_bit

    level = "quick"
    t = time.perf_counter()
    native = gartowen.verify(owen_per_bit, 2, 32, level=level, claims="owen",
                             expect="owen-per-bit-hash", batch_seeds=batch_seeds)
    total = time.perf_counter() - t
    return {
        "level": level,
        "batch_seeds": batch_seeds,
        "numpy_owen_total_s": total,
        "inside_python_fn_s": native.python_seconds,
        "battery_overhead_s": total - native.python_seconds,
        "calls": native.python_calls,
        "words": native.python_words,
        "passed": native.passed,
    }


def builtin_battery_seconds(cli):
    """Best of three runs of the same battery on the built-in twin (a run is about 0.2 s)."""
    import subprocess
    import tempfile

    with tempfile.TemporaryDirectory() as d:
        cmd = [cli, "verify", "--level", "quick", "--impl", "owen-per-bit-hash",
               "--json", f"{d}/v.json"]
        return best_of(3, lambda: subprocess.run(cmd, check=True, capture_output=True))[0]


if __name__ == "__main__":
    report = {"discrepancy": discrepancy_rows(), "verify": verify_split(True),
              "verify_one_seed_per_call": verify_split(False)}
    cli = sys.argv[1] if len(sys.argv) > 1 else "target/release/gartowen"
    twin = builtin_battery_seconds(cli)
    for key in ["verify", "verify_one_seed_per_call"]:
        v = report[key]
        v["builtin_twin_battery_s"] = twin
        v["overhead_over_twin"] = v["battery_overhead_s"] / twin
        v["total_over_twin"] = v["numpy_owen_total_s"] / twin
    print(json.dumps(report, indent=2))
