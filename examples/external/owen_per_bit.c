/* A correct external scrambler: binary Owen scrambling with one hashed flip per tree node,
 * the twin of gartowen's built-in `owen-per-bit-hash` (bit-exact, 32- and 64-bit words).
 *
 * Node (k, prefix) of dimension `dim` flips output bit k (from the top) iff the low bit of
 * mix64(key ^ mix64((k << 58) ^ prefix)) is set, where prefix is the input's top k bits and
 * key = hash_words(seed, dim). Build: cc -O2 -o owen_per_bit owen_per_bit.c */
#include "protocol.h"

static uint64_t mix64(uint64_t z) { /* the SplitMix64 finalizer */
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static const uint64_t GAMMA = 0x9E3779B97F4A7C15ull;

static uint64_t hash_words2(uint64_t a, uint64_t b) {
    uint64_t h = GAMMA;
    h = mix64(h ^ mix64(a + GAMMA));
    return mix64(h ^ mix64(b + GAMMA));
}

static uint64_t scramble(uint64_t x, unsigned width, uint32_t base, uint32_t dim, uint64_t seed) {
    if (base != 2) {
        fprintf(stderr, "owen_per_bit: base %u is not 2\n", base);
        exit(4);
    }
    uint64_t key = hash_words2(seed, dim);
    uint64_t y = x;
    for (unsigned k = 0; k < width; k++) {
        uint64_t prefix = k == 0 ? 0 : x >> (width - k);
        uint64_t flip = mix64(key ^ mix64(((uint64_t)k << 58) ^ prefix)) & 1;
        y ^= flip << (width - 1 - k);
    }
    return y;
}

int main(int argc, char **argv) {
    (void)argc;
    return serve(argv[0]);
}
