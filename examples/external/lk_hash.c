/* Laine-Karras style hashing on reversed bits, the binary "Owen scrambling" several renderers
 * and sampling libraries ship: y = reverse(hash(reverse(x), seed_dim)) on 32-bit words. Run with
 * the argument `improved` for the improved LK hash. It is nested (output bit k depends only on
 * input bits 0..k), but its node flips obey exact GF(2) relations: claiming Owen, it must fail
 * `gartowen verify`'s flip-rank test. Build: cc -O2 -o lk_hash lk_hash.c */
#include "protocol.h"

static int improved;

static uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Bit reversal: a byte swap, then nibbles, pairs and bits within each byte (the every-word sweep
 * sends 2^32 words per dimension, so this is most of the program's time). */
static inline uint32_t reverse32(uint32_t v) {
    v = __builtin_bswap32(v);
    v = ((v >> 4) & 0x0F0F0F0Fu) | ((v & 0x0F0F0F0Fu) << 4);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    return ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
}

static uint32_t lk(uint32_t x, uint32_t s) {
    x += s;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

static uint32_t lk_improved(uint32_t x, uint32_t s) {
    x ^= x * 0x3d20adeau;
    x += s;
    x *= (s >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

static uint64_t scramble(uint64_t x, unsigned width, uint32_t base, uint32_t dim, uint64_t seed) {
    (void)base;
    if (width != 32) {
        fprintf(stderr, "lk_hash: 32-bit words only\n");
        exit(3);
    }
    /* The dimension's key, computed once per (seed, dim) rather than once per word. */
    static uint64_t cached_seed, cached_dim = UINT64_MAX;
    static uint32_t s;
    if (seed != cached_seed || dim != cached_dim) {
        s = (uint32_t)mix64(mix64(seed) + dim);
        cached_seed = seed;
        cached_dim = dim;
    }
    uint32_t r = reverse32((uint32_t)x);
    return reverse32(improved ? lk_improved(r, s) : lk(r, s));
}

int main(int argc, char **argv) {
    improved = argc > 1 && strcmp(argv[1], "improved") == 0;
    return serve(argv[0]);
}
