/* The protocol's request loop for the hostile test programs: answers up to `most` requests
 * with their words unchanged (most < 0: until stdin closes). Returns 0 at the end of stdin,
 * 3 on a truncated or oversized request, 1 after `most` answers. */
#include <stdint.h>
#include <stdio.h>

static unsigned char echo_buf[8u << 20];

static int echo_frames(long most) {
    for (long served = 0; most < 0 || served < most; served++) {
        unsigned char header[32];
        size_t got = fread(header, 1, sizeof header, stdin);
        if (got == 0 && feof(stdin)) return 0;
        if (got != sizeof header) return 3;
        unsigned width = header[6] | (unsigned)header[7] << 8;
        uint32_t count = header[16] | (uint32_t)header[17] << 8 | (uint32_t)header[18] << 16 |
                         (uint32_t)header[19] << 24;
        size_t bytes = (size_t)count * (width / 8);
        if (bytes > sizeof echo_buf || fread(echo_buf, 1, bytes, stdin) != bytes) return 3;
        unsigned char reply[8] = {'G', 'O', 'W', 'R', header[16], header[17], header[18],
                                  header[19]};
        fwrite(reply, 1, sizeof reply, stdout);
        fwrite(echo_buf, 1, bytes, stdout);
        fflush(stdout);
    }
    return 1;
}
