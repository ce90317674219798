/* A true nested uniform (Owen) scramble in a base b that is not a power of two (version-2
 * requests: base-b digit integers): node (depth k, original prefix p) permutes the b digits by
 * a Fisher-Yates shuffle keyed by (seed, dim, k, p). It must pass every check of
 * `gartowen verify --external ./owen_radix --base 3` (and 5, 6, 7, …). Build:
 * cc -O2 -o owen_radix owen_radix.c */
#include "radix_digits.h" /* first: it selects version 2 */
#include "protocol.h"

static uint64_t node_key(uint64_t dim_key, unsigned depth, uint64_t prefix) {
    return mix64(dim_key ^ mix64(((uint64_t)depth << 56) ^ mix64(prefix)));
}

static uint64_t scramble(uint64_t x, unsigned width, uint32_t base, uint32_t dim, uint64_t seed) {
    uint64_t dim_key = mix64(mix64(seed) ^ mix64(0x5EEDull + dim));
    return scramble_digits(x, width, base, dim_key, node_key, shuffled);
}

int main(int argc, char **argv) {
    (void)argc;
    return serve(argv[0]);
}
