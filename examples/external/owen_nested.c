/* A true nested uniform (Owen) scramble in any base b = 2^q the request names: the permutation
 * of node (depth k, original prefix p) is a Fisher-Yates shuffle of the b digits (2^r for a
 * partial tail digit of r bits) drawn from a SplitMix64 stream keyed by (seed, dim, k, p), with
 * unbiased bounded draws. It is not bit-exact with the built-in oracle (another keying); it
 * must pass every check of `gartowen verify` in every base. Build:
 * cc -O2 -o owen_nested owen_nested.c */
#include "protocol.h"

static uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static uint64_t next(uint64_t *state) {
    *state += 0x9E3779B97F4A7C15ull;
    return mix64(*state);
}

/* Uniform in 0..n-1 by rejection (n a power of two up to 256, so a mask suffices). */
static unsigned bounded(uint64_t *state, unsigned n) {
    for (;;) {
        unsigned v = (unsigned)(next(state) & 255u);
        if (v < 256u - 256u % n) return v % n;
    }
}

static unsigned node_image(uint64_t key, unsigned bits, unsigned d) {
    unsigned perm[256];
    unsigned n = 1u << bits;
    for (unsigned i = 0; i < n; i++) perm[i] = i;
    uint64_t state = key;
    for (unsigned i = n - 1; i > 0; i--) {
        unsigned j = bounded(&state, i + 1);
        unsigned t = perm[i];
        perm[i] = perm[j];
        perm[j] = t;
    }
    return perm[d];
}

static uint64_t scramble(uint64_t x, unsigned width, uint32_t base, uint32_t dim, uint64_t seed) {
    unsigned q = 0;
    while ((1u << q) < base) q++;
    uint64_t dim_key = mix64(mix64(seed) ^ mix64(0x5EEDull + dim));
    uint64_t y = 0, prefix = 0;
    unsigned used = 0;
    for (unsigned k = 0; used < width; k++) {
        unsigned bits = width - used < q ? width - used : q;
        unsigned shift = width - used - bits;
        unsigned d = (unsigned)((x >> shift) & ((1u << bits) - 1u));
        uint64_t key = mix64(dim_key ^ mix64(((uint64_t)k << 56) ^ mix64(prefix)));
        y |= (uint64_t)node_image(key, bits, d) << shift;
        prefix = (prefix << bits) | d;
        used += bits;
    }
    return y;
}

int main(int argc, char **argv) {
    (void)argc;
    return serve(argv[0]);
}
