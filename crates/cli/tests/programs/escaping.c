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

static unsigned char buf[8u << 20];

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
    for (;;) {
        unsigned char header[32];
        if (fread(header, 1, sizeof header, stdin) != sizeof header) return 0;
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
}
