/* A deliberately broken external scrambler: a seeded bijective hash of the whole word. It is
 * a permutation of words (so it passes the injectivity check), but the top output digits
 * depend on the low input digits, so it is not a nested scramble: `gartowen verify` must
 * reject it and name the node where nestedness fails. Build: cc -O2 -o broken_hash broken_hash.c */
#include "protocol.h"

static uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static uint32_t fmix32(uint32_t h) { /* MurmurHash3's finalizer: a bijection of 32-bit words */
    h ^= h >> 16;
    h *= 0x85EBCA6Bu;
    h ^= h >> 13;
    h *= 0xC2B2AE35u;
    return h ^ (h >> 16);
}

static uint64_t scramble(uint64_t x, unsigned width, uint32_t base, uint32_t dim, uint64_t seed) {
    (void)base;
    uint64_t key = mix64(seed * 0x9E3779B97F4A7C15ull + dim);
    return width == 32 ? fmix32((uint32_t)(x ^ key)) : mix64(x ^ key);
}

int main(int argc, char **argv) {
    (void)argc;
    return serve(argv[0]);
}
