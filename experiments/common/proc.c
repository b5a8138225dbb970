/* Runs in-process or as programs (proc.h). */
#include "common/proc.h"
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <sys/wait.h>
#include <unistd.h>

static int count(char **argv)
{
    int n = 0;
    while (argv[n])
        n++;
    return n;
}

/* stdout and stderr into log; the previous descriptors into saved (when saved is not NULL). */
static int redirect(const char *log, int saved[2])
{
    fflush(NULL);
    int fd = open(log ? log : "/dev/null", O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) return -1;
    if (saved) saved[0] = dup(1), saved[1] = dup(2);
    dup2(fd, 1);
    dup2(fd, 2);
    close(fd);
    return 0;
}

static void restore(int saved[2])
{
    fflush(NULL);
    dup2(saved[0], 1);
    dup2(saved[1], 2);
    close(saved[0]);
    close(saved[1]);
}

/* In a child: the call or the program, its output into log. */
static int in_child(const struct proc_prog *p, char **argv, const char *log)
{
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) return -1;
    if (pid == 0) {
        if (redirect(log, NULL) < 0) _exit(127);
        if (p->main) {
            int st = p->main(count(argv), argv);
            fflush(NULL);
            _exit(st);
        }
        execv(argv[0], argv);
        _exit(127);
    }
    int st;
    while (waitpid(pid, &st, 0) < 0)
        if (errno != EINTR) return -1;
    return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + (WIFSIGNALED(st) ? WTERMSIG(st) : 0);
}

int proc_run(const struct proc_prog *p, char **argv, const char *log)
{
    if (!p->main) return in_child(p, argv, log);
    int saved[2];
    if (redirect(log, saved) < 0) return -1;
    int st = p->main(count(argv), argv);
    restore(saved);
    return st;
}

int proc_probe(const struct proc_prog *p, char **argv) { return in_child(p, argv, NULL); }

int proc_render_resumable(const char *prog, const struct proc_prog *p, char **rv, int c, const char *prefix,
                          double every, const char *log)
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
        int st = proc_run(p, rv, log);
        if (st == 0) unlink(ck);
        if (st != 2) return st;
        fprintf(stderr, "%s: %s was not resumable (see %s); starting over\n", prog, ck, log ? log : "its log");
        unlink(ck);
    }
    rv[c] = NULL;
    int st = proc_run(p, rv, log);
    if (st == 0 && every > 0) unlink(ck); /* complete: its outputs are what a rerun keeps */
    return st;
}
