/* examples/external/owen_radix.c itself, counting what it is sent: every request header and
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
/* The example itself, its main renamed so that this one can count around it. */
#define main owen_radix_main
#include "owen_radix.c"
#undef main

int main(int argc, char **argv) {
    atexit(report);
    return owen_radix_main(argc, argv);
}
