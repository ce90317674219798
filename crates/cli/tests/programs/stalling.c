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

#include "echo_frames.h"

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
    int rc = echo_frames(answers);
    if (rc != 1) return 3; /* stdin ended or a bad request before the answers were given */
    if (strcmp(mode, "sigstop") == 0) raise(SIGSTOP);
    wait_forever();
}
