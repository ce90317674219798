/* owen_radix.c's base-b Owen scramble, counting what it is sent: every request header and
 * every word read go through counted_fread, and at exit "REQUESTS WORDS" is appended to the
 * file named by COUNT_FILE. The request table of `verify --list-requests` must equal it.
 * Build: cc -O2 -I examples/external -o counting_radix counting_radix.c */
#include <stdio.h>
#include <stdlib.h>

static unsigned long long requests, words;

static size_t counted_fread(void *p, size_t size, size_t n, FILE *f) {
    size_t got = fread(p, size, n, f);
    if (size == 1 && n == 32) {
        requests += got == 32;
    } else {
        words += got;
    }
    return got;
}

static void report(void) {
    const char *path = getenv("COUNT_FILE");
    FILE *out = path ? fopen(path, "a") : NULL;
    if (out) {
        fprintf(out, "%llu %llu\n", requests, words);
        fclose(out);
    }
}

#define fread counted_fread
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
    atexit(report);
    return serve(argv[0]);
}
