/* An imitation of Owen scrambling in base b (not a power of two): every node adds its own
 * random shift, d -> d + u mod b, u uniform and independent across nodes. It is a nested
 * scramble uniform over the cyclic group Z_b only: `gartowen verify --external
 * ./cyclic_shift_radix --base 3 --claim independent:cyclic` passes, and the default claim
 * (owen) fails the node law at depth 0 (3 of the 6 permutations of S_3 never occur). Build:
 * cc -O2 -o cyclic_shift_radix cyclic_shift_radix.c */
#include "radix_digits.h" /* first: it selects version 2 */
#include "protocol.h"

static uint64_t node_key(uint64_t dim_key, unsigned depth, uint64_t prefix) {
    return mix64(dim_key ^ mix64(((uint64_t)depth << 56) ^ mix64(prefix)));
}

static uint32_t shift(uint64_t key, uint32_t base, uint32_t d) {
    uint64_t state = key;
    return (d + bounded(&state, base)) % base;
}

static uint64_t scramble(uint64_t x, unsigned width, uint32_t base, uint32_t dim, uint64_t seed) {
    uint64_t dim_key = mix64(mix64(seed) ^ mix64(0xC7C1ull + dim));
    return scramble_digits(x, width, base, dim_key, node_key, shift);
}

int main(int argc, char **argv) {
    (void)argc;
    return serve(argv[0]);
}
