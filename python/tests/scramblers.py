"""Vectorized NumPy scramblers written for the tests, independent of the package's code.

* ``owen_per_bit``: a per-node binary Owen scramble, bit k of the output flipped by a hash of
  (seed, dim, k, the input's top k bits); written to equal the built-in ``owen-per-bit-hash``
  bit for bit (SplitMix64 finalizer, hash_words(seed, dim) as the key).
* ``digital_shift``: y = x XOR S(seed, dim): every node permutation a uniform translation, but
  all nodes of a depth share it; an imitation of Owen scrambling.
"""

import numpy as np

MASK = (1 << 64) - 1
GAMMA = 0x9E3779B97F4A7C15


def mix64_int(z):
    """The SplitMix64 finalizer on a Python int (exact, no overflow warnings)."""
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
    return z ^ (z >> 31)


def hash_words_int(*words):
    h = GAMMA
    for w in words:
        h = mix64_int(h ^ mix64_int((w + GAMMA) & MASK))
    return h


_M1 = np.uint64(0xBF58476D1CE4E5B9)
_M2 = np.uint64(0x94D049BB133111EB)


def mix64(z):
    """The SplitMix64 finalizer on a uint64 array (wrapping multiplication)."""
    z = (z ^ (z >> np.uint64(30))) * _M1
    z = (z ^ (z >> np.uint64(27))) * _M2
    return z ^ (z >> np.uint64(31))


def seed_key(seed, dim):
    """hash_words(seed, dim) for an int seed, or elementwise for a uint64 array of seeds."""
    if isinstance(seed, np.ndarray):
        gamma = np.uint64(GAMMA)
        h = mix64(gamma ^ mix64(seed.astype(np.uint64) + gamma))
        return mix64(h ^ np.uint64(mix64_int((dim + GAMMA) & MASK)))
    return np.uint64(hash_words_int(seed, dim))


def owen_per_bit(words, dim, seed):
    """Elementwise in (words, seed): with a (rows, 1) array of seeds and (rows, n) words, row i
    is seed i's scramble (``gartowen.verify(..., batch_seeds=True)``). Every level at once, in
    blocks of words, because the battery calls it thousands of times (a loop over the levels
    costs a thousand NumPy calls per call); above 2^14 words the level loop in place is faster."""
    if words.size > 1 << 14:
        return _owen_per_bit_by_level(words, dim, seed)
    width = 32 if words.dtype == np.uint32 else 64
    x = words.astype(np.uint64)
    key = seed_key(seed, dim)
    x, key = (np.ascontiguousarray(a).ravel() for a in np.broadcast_arrays(x, key))
    k = np.arange(width, dtype=np.uint64)
    # (x >> 1) >> (width - 1 - k) is x's top k bits, 0 at k = 0 (a shift by the whole width is
    # not defined).
    shift = np.uint64(width - 1) - k
    level = (k << np.uint64(58)) & np.uint64(MASK)
    y = np.empty_like(x)
    block = 1 << 12
    for i in range(0, len(x), block):
        xs = x[i:i + block]
        # bit k flipped by mix64(key ^ mix64(level ^ prefix)) & 1.
        z = mix64(((xs >> np.uint64(1))[:, None] >> shift[None, :]) ^ level[None, :])
        z = mix64(z ^ key[i:i + block, None]) & np.uint64(1)
        y[i:i + block] = xs ^ (z << shift[None, :]).sum(axis=1, dtype=np.uint64)
    return y.reshape(np.broadcast(words, seed_key(seed, dim)).shape).astype(words.dtype)


def _mix64_inplace(z, tmp):
    """mix64 written into z, with tmp (same shape) as scratch: no temporaries per step."""
    for shift, mult in ((30, _M1), (27, _M2), (31, None)):
        np.right_shift(z, np.uint64(shift), out=tmp)
        np.bitwise_xor(z, tmp, out=z)
        if mult is not None:
            np.multiply(z, mult, out=z)


def _owen_per_bit_by_level(words, dim, seed):
    """owen_per_bit level by level, in place (one scratch pair of arrays for all 32 or 64
    levels): the faster form for millions of words."""
    width = 32 if words.dtype == np.uint32 else 64
    x = words.astype(np.uint64)
    key = seed_key(seed, dim)
    y = x.copy()
    z = np.empty(np.broadcast(x, key).shape, dtype=np.uint64)
    tmp = np.empty_like(z)
    for k in range(width):
        # z = mix64(key ^ mix64(level ^ prefix)) & 1, prefix the top k bits of x.
        if k:
            np.right_shift(x, np.uint64(width - k), out=z)
        else:
            z.fill(0)
        np.bitwise_xor(z, np.uint64((k << 58) & MASK), out=z)
        _mix64_inplace(z, tmp)
        np.bitwise_xor(z, key, out=z)
        _mix64_inplace(z, tmp)
        np.bitwise_and(z, np.uint64(1), out=z)
        np.left_shift(z, np.uint64(width - 1 - k), out=z)
        np.bitwise_xor(y, z, out=y)
    return y.astype(words.dtype)


def digital_shift(words, dim, seed):
    width = 32 if words.dtype == np.uint32 else 64
    shift = hash_words_int(seed, dim) >> (64 - width)
    return words ^ words.dtype.type(shift)
