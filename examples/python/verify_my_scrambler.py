#!/usr/bin/env python3
"""Verify your own vectorized Owen scrambler with gartowen, from Python.

Write the scrambler as fn(words, dim, seed) -> words, where words is a 1-D uint32 array of
32-bit words (value = word * 2^-32), dim the dimension and seed an integer in [0, 2^64); it
returns the scrambled words, same shape and dtype. Written elementwise in (words, seed), as
below, it also takes many seeds per call (batch_seeds=True: words of shape (rows, n), seeds
of shape (rows, 1)), which makes the battery about ten times faster. gartowen.verify runs the battery that
`gartowen verify` runs on built-in and external implementations: structure exactly
(injectivity, nestedness, nets kept), randomness by marginal and joint laws over seeds 0, 1,
2, ..., judged on what you claim, at a family-wise false-alarm rate of 1e-3.

This example verifies two scramblers:
  * a per-node binary Owen scramble (one hashed flip per tree node): it passes as "owen";
  * a random digital shift (one flip per depth, shared by every node of that depth): an
    imitation. It passes what it really is, marginal:translation, and fails as "owen",
    on the joint laws (nodes of one depth are not independent).

Run:  pip install ./python  &&  python examples/python/verify_my_scrambler.py
Exit code: 0 when both verdicts are as expected.
"""

import sys

import numpy as np

import gartowen

MASK = (1 << 64) - 1


def mix64(z):
    """SplitMix64's finalizer on uint64 arrays (multiplication wraps)."""
    z = (z ^ (z >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
    z = (z ^ (z >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
    return z ^ (z >> np.uint64(31))


def key_of(seed, dim):
    """A 64-bit key per (seed, dim): shape (1,) for an int seed, else the seeds' shape.
    Arrays, not NumPy scalars, so that the wrapping multiplication raises no warning."""
    s = np.array([seed], dtype=np.uint64) if isinstance(seed, int) else seed
    return mix64(s * np.uint64(0x9E3779B97F4A7C15) + np.uint64(dim + 1))


def my_owen(words, dim, seed):
    """Binary Owen scrambling: output bit k flips iff a hash of (key, k, top k input bits) is odd."""
    x = words.astype(np.uint64)
    key = key_of(seed, dim)
    y = x.copy()
    for k in range(32):
        prefix = (x >> np.uint64(32 - k)) if k else np.zeros_like(x)
        node = prefix | np.uint64(1 << k)  # a distinct id for every node of the tree
        flip = mix64(key ^ mix64(node)) & np.uint64(1)
        y ^= flip << np.uint64(31 - k)
    return y.astype(np.uint32)


def my_shift(words, dim, seed):
    """A random digital shift: y = x XOR s(seed, dim)."""
    return words ^ (key_of(seed, dim) >> np.uint64(32)).astype(np.uint32)


def main():
    ok = True
    for fn, claim, expect_pass in [
        (my_owen, "owen", True),
        (my_shift, "marginal:translation", True),
        (my_shift, "owen", False),
    ]:
        r = gartowen.verify(fn, base=2, width=32, claims=claim, batch_seeds=True)
        print(r)
        print()
        ok &= r.passed == expect_pass
    print("as expected" if ok else "UNEXPECTED verdicts")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
