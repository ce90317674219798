#!/usr/bin/env python3
"""Owen scrambling in a base b that is not a power of two, as an external program (NumPy).

Speaks version 2 of the gartowen external protocol (docs/external.md): each request carries
integers below b^m (m base-b digits, the most whose b^m fits the word, most significant first)
and the reply carries their images. Every node of the tree (dimension, depth, input digits
above it) gets its own uniform permutation of the b digits: the ranks of b hashed keys, which
is a uniform draw from S_b up to ties of 64-bit keys. Judged on `owen`, it passes:

    gartowen verify --external "python3 examples/external/owen_radix.py" --base 3

With --per-depth every node of a depth shares one permutation (the node key ignores the digits
above it), as scrambled Halton does: each node is still uniform, nodes are not independent,
and the battery fails it on the joint laws (pair-law, collisions, pair-lemma).

Exit status: 0 when stdin closes, 3 on a request it cannot serve (version 1 or a power of two).
"""

import struct
import sys

import numpy as np

MASK = (1 << 64) - 1
HEADER = struct.Struct("<4sHHIII4xQ")


def mix64(z):
    """SplitMix64's finalizer on uint64 arrays (multiplication wraps)."""
    z = (z ^ (z >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
    z = (z ^ (z >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
    return z ^ (z >> np.uint64(31))


def digits_in(base, width):
    """m: the most base-b digits with b^m <= 2^width."""
    m, p = 0, base
    while p <= 1 << width:
        m, p = m + 1, p * base
    return m


def scramble(words, base, width, dim, seed, per_depth):
    """Images of `words` (uint64 integers below base^m) under the node permutations.

    All m depths at once, in blocks of words: the digits, the prefixes above each digit and
    the node keys are (words, m) arrays and the digit keys (words, m, b), so a request costs
    a few dozen NumPy calls instead of a few dozen per digit."""
    m = digits_in(base, width)
    x = np.asarray(words).astype(np.uint64).ravel()
    block = max(1, (1 << 21) // (m * base))
    return np.concatenate(
        [_scramble_block(x[i:i + block], base, m, dim, seed, per_depth)
         for i in range(0, len(x), block)] or [x]
    ).reshape(np.shape(words))


def _scramble_block(x, base, m, dim, seed, per_depth):
    b = np.uint64(base)
    # place[d] = b^(m-1-d): the weight of digit d, most significant first.
    place = np.array([base ** (m - 1 - d) for d in range(m)], dtype=np.uint64)
    digit = (x[:, None] // place[None, :]) % b
    prefix = x[:, None] // (place[None, :] * b)  # the digits above digit d, as an integer
    dim_key = mix64(np.array([(seed * 0x9E3779B97F4A7C15 + dim + 1) & MASK], dtype=np.uint64))
    depth = np.arange(1, m + 1, dtype=np.uint64)
    node = np.broadcast_to(mix64(dim_key + depth * np.uint64(0x9E3779B97F4A7C15)), digit.shape)
    if not per_depth:
        node = mix64(node ^ mix64(prefix + np.uint64(0x632BE59BD9B4E019)))
    # keys[i, d, c]: the key of digit value c at word i's depth-d node; an image is a rank.
    offsets = np.arange(base, dtype=np.uint64) * np.uint64(0xD1B54A32D192ED03)
    keys = mix64(node[:, :, None] ^ offsets[None, None, :])
    mine = np.take_along_axis(keys, digit.astype(np.int64)[:, :, None], axis=2)
    image = (keys < mine).sum(axis=2, dtype=np.uint64)
    return (image * place[None, :]).sum(axis=1, dtype=np.uint64)


def serve(per_depth):
    stdin, stdout = sys.stdin.buffer, sys.stdout.buffer
    while True:
        header = stdin.read(HEADER.size)
        if not header:
            return 0
        if len(header) != HEADER.size:
            print("owen_radix.py: truncated request header", file=sys.stderr)
            return 3
        magic, version, width, base, dim, count, seed = HEADER.unpack(header)
        if magic != b"GOWQ" or version != 2 or width not in (32, 64) or not 0 < count <= 1 << 20:
            print(
                f"owen_radix.py: unsupported request (version {version}, width {width}, "
                f"count {count}): this program serves version 2 (bases that are not 2^q)",
                file=sys.stderr,
            )
            return 3
        dtype = np.dtype("<u4") if width == 32 else np.dtype("<u8")
        body = stdin.read(count * dtype.itemsize)
        if len(body) != count * dtype.itemsize:
            print("owen_radix.py: truncated request", file=sys.stderr)
            return 3
        words = np.frombuffer(body, dtype=dtype)
        images = scramble(words, base, width, dim, seed, per_depth).astype(dtype)
        stdout.write(b"GOWR" + struct.pack("<I", count) + images.tobytes())
        stdout.flush()


if __name__ == "__main__":
    flags = sys.argv[1:]
    if flags not in ([], ["--per-depth"]):
        print("usage: owen_radix.py [--per-depth]", file=sys.stderr)
        sys.exit(2)
    sys.exit(serve(per_depth=flags == ["--per-depth"]))
