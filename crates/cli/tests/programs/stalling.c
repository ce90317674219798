/* A hostile external program for the containment tests: it answers the first N requests of
 * the gartowen protocol with the words unchanged, then misbehaves as MODE says, and never
 * exits by itself:
 *   never    reads nothing at all (N is ignored);
 *   stop     stops reading its stdin and waits;
 *   sigstop  stops itself with SIGSTOP.
 * It first appends its pid (its process group, since the host starts it as a group leader) to
 * PIDFILE (the host may start several) and forks a helper that waits in the same group, so that a host that kills only the
 * program leaves the helper behind.
 * Usage: stalling MODE N PIDFILE */
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static unsigned char buf[8u << 20];

static void wait_forever(void) {
    for (;;) pause();
}

int main(int argc, char **argv) {
    if (argc != 4) {
        fprintf(stderr, "usage: stalling never|stop|sigstop N PIDFILE\n");
        return 2;
    }
    const char *mode = argv[1];
    long answers = strtol(argv[2], NULL, 10);
    FILE *pidfile = fopen(argv[3], "a");
    if (!pidfile) return 2;
    fprintf(pidfile, "%ld\n", (long)getpid());
    fclose(pidfile);
    if (fork() == 0) wait_forever();
    if (strcmp(mode, "never") == 0) wait_forever();
    for (long served = 0; served < answers; served++) {
        unsigned char header[32];
        if (fread(header, 1, sizeof header, stdin) != sizeof header) return 3;
        unsigned width = header[6] | (unsigned)header[7] << 8;
        uint32_t count = header[16] | (uint32_t)header[17] << 8 | (uint32_t)header[18] << 16 |
                         (uint32_t)header[19] << 24;
        size_t bytes = (size_t)count * (width / 8);
        if (bytes > sizeof buf || fread(buf, 1, bytes, stdin) != bytes) return 3;
        unsigned char reply[8] = {'G', 'O', 'W', 'R', header[16], header[17], header[18],
                                  header[19]};
        fwrite(reply, 1, sizeof reply, stdout);
        fwrite(buf, 1, bytes, stdout);
        fflush(stdout);
    }
    if (strcmp(mode, "sigstop") == 0) raise(SIGSTOP);
    wait_forever();
}
