/* The gartowen external-scrambler protocol, versions 1 and 2 (see docs/external.md):
 * little-endian request frames on stdin, replies on stdout. Version 1 requests name a base
 * b = 2^q and carry W-bit binary fractions; version 2 requests name any other base b and carry
 * integers below b^m (m base-b digits, the most that fit W bits; radix_digits.h).
 *
 * A scrambler includes this file, defines
 *     uint64_t scramble(uint64_t x, unsigned width, uint32_t base, uint32_t dim, uint64_t seed);
 * and calls serve(argv[0]) from main.
 *
 * A program for version 2 (base-b digit integers) defines SERVES_BASE_B_DIGITS before including
 * this file (radix_digits.h does); every other program serves version 1 only, and exits with
 * status 3 on a request of the other version.
 *
 * Built with -DSERVED_DIMS=N, the program serves dimensions 0..N-1 only and exits with status 4
 * on a request for another (a sampler with N dimensions per domain); verify it with
 * `gartowen verify --external ./prog --max-dims N`.
 *
 * Built with -DSCRAMBLED_BITS=K (version 1), the reply keeps the input's bits below the top K
 * (a library that scrambles only the bits its point count needs); verify it with
 * `gartowen verify --external ./prog --bits K`. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint64_t scramble(uint64_t x, unsigned width, uint32_t base, uint32_t dim, uint64_t seed);

#ifdef SERVES_BASE_B_DIGITS
#define SERVED_VERSION 2u
#else
#define SERVED_VERSION 1u
#endif

static uint64_t get_le(const unsigned char *p, unsigned n) {
    uint64_t v = 0;
    for (unsigned i = 0; i < n; i++) v |= (uint64_t)p[i] << (8 * i);
    return v;
}

static void put_le(unsigned char *p, uint64_t v, unsigned n) {
    for (unsigned i = 0; i < n; i++) p[i] = (unsigned char)(v >> (8 * i));
}

/* Replaces the word at p (n bytes, little-endian) with its image. */
static inline void serve_word(unsigned char *p, unsigned n, unsigned width, uint32_t base,
                              uint32_t dim, uint64_t seed) {
    uint64_t x = get_le(p, n);
    uint64_t y = scramble(x, width, base, dim, seed);
#ifdef SCRAMBLED_BITS
    uint64_t low = (width - SCRAMBLED_BITS >= 64) ? ~0ull : (1ull << (width - SCRAMBLED_BITS)) - 1;
    y = (y & ~low) | (x & low);
#endif
    put_le(p, y, n);
}

static int serve(const char *self) {
    unsigned char header[32];
    static unsigned char buf[8u << 20];
    for (;;) {
        size_t got = fread(header, 1, sizeof header, stdin);
        if (got == 0 && feof(stdin)) return 0; /* the host closed stdin: done */
        if (got != sizeof header || memcmp(header, "GOWQ", 4) != 0) {
            fprintf(stderr, "%s: bad request header\n", self);
            return 3;
        }
        unsigned version = (unsigned)get_le(header + 4, 2);
        unsigned width = (unsigned)get_le(header + 6, 2);
        uint32_t base = (uint32_t)get_le(header + 8, 4);
        uint32_t dim = (uint32_t)get_le(header + 12, 4);
        uint32_t count = (uint32_t)get_le(header + 16, 4);
        uint64_t seed = get_le(header + 24, 8);
        if (version != SERVED_VERSION || (width != 32 && width != 64) || count == 0 ||
            count > (1u << 20)) {
            fprintf(stderr, "%s: unsupported request (version %u, width %u, count %u)\n", self,
                    version, width, count);
            return 3;
        }
#ifdef SERVED_DIMS
        if (dim >= SERVED_DIMS) {
            fprintf(stderr, "%s: dimension %u not served (0..%u)\n", self, dim, SERVED_DIMS - 1);
            return 4;
        }
#endif
        unsigned wb = width / 8;
        if (fread(buf, wb, count, stdin) != count) {
            fprintf(stderr, "%s: truncated request\n", self);
            return 3;
        }
        unsigned char reply_header[8];
        memcpy(reply_header, "GOWR", 4);
        put_le(reply_header + 4, count, 4);
        fwrite(reply_header, 1, sizeof reply_header, stdout);
        /* One loop per word size, so the byte loops of get_le and put_le unroll into single
         * loads and stores (the per-word cost of a fast scramble is otherwise in them). */
        if (wb == 4) {
            for (uint32_t i = 0; i < count; i++) serve_word(buf + 4 * i, 4, width, base, dim, seed);
        } else {
            for (uint32_t i = 0; i < count; i++) serve_word(buf + 8 * i, 8, width, base, dim, seed);
        }
        fwrite(buf, wb, count, stdout);
        fflush(stdout);
    }
}
