/* Subprocesses (proc.h). */
#include "common/proc.h"
#include <errno.h>
#include <stdio.h>
#include <sys/wait.h>
#include <unistd.h>

int proc_run(char *const *argv, const char *log)
{
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) return -1;
    if (pid == 0) {
        FILE *f = freopen(log ? log : "/dev/null", "w", stdout);
        (void)f;
        dup2(1, 2);
        execv(argv[0], argv);
        _exit(127);
    }
    int st;
    while (waitpid(pid, &st, 0) < 0)
        if (errno != EINTR) return -1;
    return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + (WIFSIGNALED(st) ? WTERMSIG(st) : 0);
}

int proc_render_resumable(const char *prog, char **rv, int c, const char *prefix, double every, const char *log)
{
    char every_s[32], ck[4200];
    snprintf(ck, sizeof ck, "%.4000s.ckpt", prefix);
    if (every > 0) {
        snprintf(every_s, sizeof every_s, "%g", every);
        rv[c++] = "--checkpoint";
        rv[c++] = every_s;
    }
    if (every > 0 && !access(ck, R_OK)) {
        rv[c] = "--resume", rv[c + 1] = ck, rv[c + 2] = NULL;
        int st = proc_run(rv, log);
        if (st == 0) unlink(ck);
        if (st != 2) return st;
        fprintf(stderr, "%s: %s was not resumable (see %s); starting over\n", prog, ck, log ? log : "its log");
        unlink(ck);
    }
    rv[c] = NULL;
    int st = proc_run(rv, log);
    if (st == 0 && every > 0) unlink(ck); /* complete: its outputs are what a rerun keeps */
    return st;
}
