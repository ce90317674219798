/* A base-b Owen scramble (owen_radix.c's) with one wrap-around bug: the largest word b^m − 1
 * is answered with b^m, one past the last word of the frame's width. Every other reply is the
 * true scramble, so only a host that range-checks every reply word can tell. Build from the
 * examples folder's headers: cc -O2 -I examples/external -o radix_overflow radix_overflow.c */
#include "radix_digits.h" /* first: it selects version 2 */
#include "protocol.h"

static uint64_t node_key(uint64_t dim_key, unsigned depth, uint64_t prefix) {
    return mix64(dim_key ^ mix64(((uint64_t)depth << 56) ^ mix64(prefix)));
}

static uint64_t scramble(uint64_t x, unsigned width, uint32_t base, uint32_t dim, uint64_t seed) {
    uint64_t capacity = 1;
    for (unsigned k = digits_in(base, width); k > 0; k--) capacity *= base;
    if (x == capacity - 1) return capacity;
    uint64_t dim_key = mix64(mix64(seed) ^ mix64(0x5EEDull + dim));
    return scramble_digits(x, width, base, dim_key, node_key, shuffled);
}

int main(int argc, char **argv) {
    (void)argc;
    return serve(argv[0]);
}
