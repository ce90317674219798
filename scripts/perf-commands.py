#!/usr/bin/env python3
"""Times whole gartowen commands against in-run references, and SciPy in the same run.

Every figure is the best of --repeat runs (wall clock), so the table is a set of ratios
measured minutes apart on one machine, not promises. Rows:

  dd of the same 128 MiB into a file (the write floor); generate 2^20 x 16 Sobol to .npy (a
  file in a temporary directory and /dev/null), unscrambled
  and with each scrambler, 1 and 2 threads; check of a 16-D base-16 set of 2^20 points against
  t = 0, 1 and 2 threads, with peak memory; compensated discrepancy, 1 and 2 threads; and, in
  memory through the Python package, gartowen.generate against SciPy's scrambled Sobol
  (LMS + digital shift, not Owen) of the same size, with NumPy filling a fresh array of that
  size as the floor of both.

Usage: scripts/perf-commands.py [--bin target/release/gartowen] [--repeat 3] [--json out.json]
The Python rows need `gartowen`, numpy and scipy importable by the running interpreter.
"""
import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time


def timed(cmd, threads, repeat):
    """Best wall time of `repeat` runs and the peak RSS (KiB) of the children."""
    env = dict(os.environ, RAYON_NUM_THREADS=str(threads))
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        subprocess.run(cmd, check=True, env=env, stdout=subprocess.DEVNULL)
        best = min(best, time.perf_counter() - start)
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    return best, peak


def python_rows(repeat):
    """gartowen.generate against scipy.stats.qmc.Sobol in memory (first call and warm)."""
    try:
        import gartowen
        from scipy.stats import qmc
    except ImportError as e:  # the CLI rows stand without Python
        return {"skipped": str(e)}
    out = {}

    def best_of(fn):
        first_start = time.perf_counter()
        fn()
        first = time.perf_counter() - first_start
        best = first
        for _ in range(repeat):
            start = time.perf_counter()
            fn()
            best = min(best, time.perf_counter() - start)
        return first, best

    import numpy as np
    # The floor of any call that returns a fresh (2^20, 16) float64 array: allocating it
    # and writing every element once (page faults included).
    out["numpy_fresh_array_filled"] = best_of(lambda: np.full((1 << 20, 16), 0.5))
    out["scipy_sobol_scrambled"] = best_of(
        lambda: qmc.Sobol(d=16, scramble=True, seed=1).random_base2(20))
    out["scipy_sobol_unscrambled"] = best_of(
        lambda: qmc.Sobol(d=16, scramble=False).random_base2(20))
    for s in ["none", "lk-hash", "art-owen-2", "art-owen-16p", "owen-oracle"]:
        out[f"gartowen_{s}"] = best_of(
            lambda s=s: gartowen.generate("sobol", 16, 1 << 20, scramble=s, seed=1))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default="target/release/gartowen")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--json", default=None, help="also write the figures here")
    args = ap.parse_args()
    g = os.path.abspath(args.bin)
    rows = {}
    with tempfile.TemporaryDirectory() as tmp:
        gen = [g, "generate", "--seq", "sobol", "--dims", "16", "--log2-n", "20",
               "--format", "npy", "--seed", "1"]
        # The floor of writing the 128 MiB .npy: the same bytes copied into a file by dd.
        sink = os.path.join(tmp, "dd.bin")
        rows["dd 128 MiB to a file (the write floor)"], _ = timed(
            ["dd", "if=/dev/zero", f"of={sink}", "bs=2M", "count=64", "status=none"],
            1, args.repeat)
        os.remove(sink)
        for target in ["file", "devnull"]:
            out = os.path.join(tmp, "g.npy") if target == "file" else "/dev/null"
            for s in ["none", "lk-hash", "art-owen-2", "art-owen-16p", "owen-per-bit-hash",
                      "owen-oracle"]:
                for threads in [1, 2]:
                    t, _ = timed(gen + ["--scramble", s, "-o", out], threads, args.repeat)
                    rows[f"generate {s} -> {target}, {threads} thread(s)"] = t
        net = os.path.join(tmp, "sz16.npy")
        subprocess.run([g, "generate", "--seq", "sz16", "--dims", "16", "--log2-n", "20",
                        "--scramble", "art-owen-16p", "--seed", "3", "--format", "npy",
                        "-o", net], check=True)
        for threads in [1, 2]:
            cmd = ["/usr/bin/time", "-f", "%M", g, "check", net, "--base", "16", "--t", "0",
                   "--threads", str(threads)]
            best, peak_kib = float("inf"), 0
            for _ in range(max(1, args.repeat - 1)):
                start = time.perf_counter()
                done = subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL,
                                      stderr=subprocess.PIPE, text=True)
                best = min(best, time.perf_counter() - start)
                peak_kib = int(done.stderr.strip().splitlines()[-1])
            rows[f"check 16-D base 16 N=2^20 t=0, {threads} thread(s)"] = best
            rows[f"check peak memory MB, {threads} thread(s)"] = peak_kib / 1024
        disc = os.path.join(tmp, "d.npy")
        subprocess.run([g, "generate", "--seq", "sobol", "--dims", "8", "--log2-n", "16",
                        "--scramble", "art-owen-2", "--seed", "2", "--format", "npy",
                        "-o", disc], check=True)
        for threads in [1, 2]:
            t, _ = timed([g, "discrepancy", disc, "--kind", "cd", "--method", "compensated"],
                         threads, args.repeat)
            rows[f"discrepancy cd compensated 8-D N=2^16, {threads} thread(s)"] = t
    py = python_rows(args.repeat)
    width = max(len(k) for k in rows)
    for k, v in rows.items():
        print(f"{k:<{width}}  {v:9.3f}")
    for k, v in py.items():
        if k == "skipped":
            print(f"python rows skipped: {v}")
        else:
            print(f"{('python ' + k):<{width}}  first {v[0]:7.3f}  warm {v[1]:7.3f}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"commands_s": rows, "python_first_warm_s": py}, f, indent=1)


if __name__ == "__main__":
    sys.exit(main())
