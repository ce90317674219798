/* A hostile external program for the containment tests: it leaves a grandchild behind that
 * no process-group kill and no pipe scan can find. The program forks; the child forks again
 * and exits; the grandchild calls setsid (a new session and group), appends its pid to
 * PIDFILE, closes every descriptor and waits forever. The program itself then answers every
 * request with the words unchanged and exits when its stdin closes.
 * Usage: escaping PIDFILE */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "echo_frames.h"

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: escaping PIDFILE\n");
        return 2;
    }
    pid_t child = fork();
    if (child == 0) {
        if (fork() == 0) {
            setsid();
            FILE *pidfile = fopen(argv[1], "a");
            if (pidfile) {
                fprintf(pidfile, "%ld\n", (long)getpid());
                fclose(pidfile);
            }
            for (int fd = 0; fd < 1024; fd++) close(fd);
            for (;;) pause();
        }
        _exit(0);
    }
    waitpid(child, NULL, 0);
    return echo_frames(-1);
}
