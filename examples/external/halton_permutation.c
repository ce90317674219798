/* The random digit permutation of scrambled Halton points (as in SciPy's Halton scramble): one
 * uniform permutation of the b digits per dimension and digit position, applied to that digit
 * of every point. Each node is uniform over S_b, but all nodes of a depth share one
 * permutation: `gartowen verify --external ./halton_permutation --base 3 --claim
 * marginal:symmetric` passes, and the default claim (owen) fails the joint laws (pair law,
 * collisions, pair lemma). Build: cc -O2 -o halton_permutation halton_permutation.c */
#include "radix_digits.h" /* first: it selects version 2 */
#include "protocol.h"

/* The prefix is ignored: one permutation per (dimension, depth). */
static uint64_t depth_key(uint64_t dim_key, unsigned depth, uint64_t prefix) {
    (void)prefix;
    return mix64(dim_key ^ mix64((uint64_t)depth + 1));
}

static uint64_t scramble(uint64_t x, unsigned width, uint32_t base, uint32_t dim, uint64_t seed) {
    uint64_t dim_key = mix64(mix64(seed) ^ mix64(0x4A17ull + dim));
    return scramble_digits(x, width, base, dim_key, depth_key, shuffled);
}

int main(int argc, char **argv) {
    (void)argc;
    return serve(argv[0]);
}
