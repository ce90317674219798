/* Base-b digits of version-2 words (b not a power of two): a word is an integer below b^m, m
 * the most base-b digits whose b^m fits `width` bits, digit 0 the most significant. Also the
 * SplitMix64 stream and unbiased bounded draws the base-b examples key their nodes with. */
#include <stdint.h>

#define SERVES_BASE_B_DIGITS 1

static inline unsigned digits_in(uint32_t base, unsigned width) {
    unsigned m = 0;
    unsigned __int128 p = base, limit = (unsigned __int128)1 << width;
    while (p <= limit) {
        m++;
        p *= base;
    }
    return m;
}

static uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static inline uint64_t next(uint64_t *state) {
    *state += 0x9E3779B97F4A7C15ull;
    return mix64(*state);
}

/* Uniform in 0..n-1 (n ≤ 2^32) by rejection of the surplus of 32-bit draws. */
static inline uint32_t bounded(uint64_t *state, uint32_t n) {
    uint64_t limit = (1ull << 32) - (1ull << 32) % n;
    for (;;) {
        uint64_t v = next(state) >> 32;
        if (v < limit) return (uint32_t)(v % n);
    }
}

/* Image of d under the Fisher-Yates shuffle of 0..b-1 drawn from `key` (b ≤ 65535). */
static inline uint32_t shuffled(uint64_t key, uint32_t b, uint32_t d) {
    static uint32_t perm[65536];
    for (uint32_t i = 0; i < b; i++) perm[i] = i;
    uint64_t state = key;
    for (uint32_t i = b - 1; i > 0; i--) {
        uint32_t j = bounded(&state, i + 1);
        uint32_t t = perm[i];
        perm[i] = perm[j];
        perm[j] = t;
    }
    return perm[d];
}

/* Applies `image(key_of_node, digit)` digit by digit, most significant first; the node key
 * comes from `node_key(dim_key, depth, prefix)`, prefix the input digits above the node. */
typedef uint64_t (*node_key_fn)(uint64_t dim_key, unsigned depth, uint64_t prefix);
typedef uint32_t (*image_fn)(uint64_t key, uint32_t base, uint32_t d);

static inline uint64_t scramble_digits(uint64_t x, unsigned width, uint32_t base, uint64_t dim_key,
                                node_key_fn node_key, image_fn image) {
    unsigned m = digits_in(base, width);
    uint64_t place = 1;
    for (unsigned k = 1; k < m; k++) place *= base;
    uint64_t y = 0, prefix = 0;
    for (unsigned k = 0; k < m; k++, place /= base) {
        uint32_t d = (uint32_t)((x / place) % base);
        y = y * base + image(node_key(dim_key, k, prefix), base, d);
        prefix = prefix * base + d;
    }
    return y;
}
