/* An imitation of Owen scrambling: a random digital shift, y = x XOR one random word per
 * (seed, dimension). Every node permutation is a fair flip, so single-node laws pass; all nodes
 * of a depth flip together, so `gartowen verify` (claim owen, the default for external
 * programs) must fail it at the joint laws. Build: cc -O2 -o digital_shift digital_shift.c */
#include "protocol.h"

static uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static uint64_t scramble(uint64_t x, unsigned width, uint32_t base, uint32_t dim, uint64_t seed) {
    (void)base;
    uint64_t shift = mix64(mix64(seed) ^ (0x9E3779B97F4A7C15ull * (dim + 1)));
    return width == 32 ? (x ^ (shift >> 32)) : (x ^ shift);
}

int main(int argc, char **argv) {
    (void)argc;
    return serve(argv[0]);
}
