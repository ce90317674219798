#!/usr/bin/env python3
"""Prints criterion's medians as time per element, with ratios against a reference.

Reads target/criterion/GROUP/ID/new/{estimates,benchmark}.json written by the last
`cargo bench` run. Usage: criterion-table.py [--ref GROUP/ID] [--group REGEX] [--json]
Ratios are only meaningful between benchmarks of one run on one machine.
"""
import argparse
import json
import pathlib
import re
import sys


def rows(root, pattern):
    for est in sorted(root.glob("**/new/estimates.json")):
        bench = est.parent / "benchmark.json"
        if not bench.exists():
            continue
        meta = json.loads(bench.read_text())
        full = meta.get("full_id") or meta.get("title")
        if pattern and not re.search(pattern, full):
            continue
        median_ns = json.loads(est.read_text())["median"]["point_estimate"]
        thr = meta.get("throughput") or {}
        elements = thr.get("Elements") or thr.get("Bytes") or 1
        yield full, median_ns / elements


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--root", default="target/criterion")
    ap.add_argument("--group", default="", help="regex on GROUP/ID")
    ap.add_argument("--ref", default=None, help="GROUP/ID every ratio is taken against")
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    table = dict(rows(pathlib.Path(args.root), args.group))
    if not table:
        sys.exit("no criterion results match; run cargo bench first")
    ref = table.get(args.ref) if args.ref else None
    if args.ref and ref is None:
        sys.exit(f"reference {args.ref} not found")
    if args.json:
        print(json.dumps({k: {"ns_per_element": v, "ratio": (v / ref if ref else None)}
                          for k, v in table.items()}, indent=1))
        return
    width = max(len(k) for k in table)
    for k, v in table.items():
        ratio = f"  {v / ref:7.3f}x" if ref else ""
        print(f"{k:<{width}}  {v:10.3f} ns{ratio}")


if __name__ == "__main__":
    main()
