#!/usr/bin/env python3
"""Regenerates gartowen's Sobol data and golden vectors from SciPy (run by hand, never by tests).

1. crates/seq/data/new-joe-kuo-6.21201.txt: Joe & Kuo's "new-joe-kuo-6.21201" direction
   numbers, in their original text format (d s a m_1 .. m_s), recovered from the copy SciPy
   ships in scipy/stats/_sobol_direction_numbers.npz. There `poly` = (1<<s) | (a<<1) | 1
   and `vinit` holds m_1..m_s (row 0 is dimension 1, the van der Corput sequence).
2. crates/seq/tests/data/scipy_sobol_*.hex: unscrambled points of scipy.stats.qmc.Sobol as hex
   words, one point per line. SciPy emits points in Gray-code order: row n is index n ^ (n >> 1).
"""
import os
import numpy as np
import scipy
from scipy.stats import qmc

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
npz = np.load(os.path.join(os.path.dirname(scipy.__file__), "stats", "_sobol_direction_numbers.npz"))
poly, vinit = npz["poly"], npz["vinit"]

with open(os.path.join(root, "crates/seq/data/new-joe-kuo-6.21201.txt"), "w") as f:
    f.write("d       s       a       m_i\n")
    for j in range(1, len(poly)):
        s = int(poly[j]).bit_length() - 1
        a = (int(poly[j]) >> 1) & ((1 << (s - 1)) - 1)
        ms = " ".join(str(int(v)) for v in vinit[j, :s])
        f.write(f"{j + 1} {s} {a} {ms}\n")

out = os.path.join(root, "crates/seq/tests/data")
os.makedirs(out, exist_ok=True)

def dump(name, d, n, bits, first_dim=0):
    eng = qmc.Sobol(d, scramble=False, bits=bits)
    if bits <= 52:
        words = (eng.random(n) * 2.0**bits).astype(np.uint64)
    else:
        # Floats cannot hold 64-bit words: replay SciPy's own Gray-code recurrence on its
        # direction vectors (engine._sv) in integers, the same order .random() uses.
        sv = eng._sv.astype(object)
        q = [0] * d
        words = []
        for i in range(n):
            words.append(list(q))
            c = ((i + 1) & -(i + 1)).bit_length() - 1  # lowest set bit of i+1
            q = [q[j] ^ int(sv[j][c]) for j in range(d)]
        words = np.array(words, dtype=np.uint64)
    width = bits // 4
    with open(os.path.join(out, name), "w") as f:
        f.write(f"# scipy {scipy.__version__} qmc.Sobol(d={d}, scramble=False, bits={bits}), rows in scipy order (index = n ^ (n >> 1)), dims {first_dim}..{d - 1}\n")
        for row in words:
            f.write(" ".join(format(int(v), f"0{width}x") for v in row[first_dim:]) + "\n")

dump("scipy_sobol_d40_n512_b32.hex", 40, 512, 32)
dump("scipy_sobol_d8_n256_b64.hex", 8, 256, 64)
dump("scipy_sobol_last12_n128_b32.hex", 21201, 128, 32, first_dim=21189)
