/* Outputs when the disk fills: a write that fails leaves the previous file as it was, removes its
 * temporary and ends the program with status 1 and one line naming the file. The failures are
 * real: the child runs under a file-size limit with SIGXFSZ ignored, so the kernel refuses its
 * writes (EFBIG) as a full disk would (ENOSPC). Where an earlier output would hit the limit first,
 * PSS_TEST_FAIL_WRITE names the one to fail and the limit applies around its writes alone
 * (core/base/util.c). */
#include <criterion/criterion.h>

#include "support/tmpdir.h"
#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#ifndef BIN_DIR
#define BIN_DIR "bin"
#endif

static char dir[64];

static void make_dir(void) { tmpdir_make(dir, sizeof dir, "disk-full"); }
static void remove_dir(void) { tmpdir_remove(dir); }
TestSuite(disk_full, .init = make_dir, .fini = remove_dir, .timeout = 60);

struct run {
    long limit;       /* bytes a file may hold, or 0 for no limit */
    const char *fail; /* PSS_TEST_FAIL_WRITE, or NULL */
    double sigint;    /* seconds before Ctrl-C, or 0 */
    bool chatty;      /* progress lines on stderr before the error line */
};

/* Runs the words of `cmd` (DIR stands for the test's directory), stdout discarded; returns the
 * exit status (128 + signal when killed) and the stderr text in err. */
static int run(const char *cmd, struct run how, char *err, size_t n)
{
    char line[2048], *argv[64];
    int argc = 0, fd[2];
    snprintf(line, sizeof line, "%s", cmd);
    for (char *t = strtok(line, " "); t && argc < 63; t = strtok(NULL, " ")) {
        static char words[64][256];
        char *d = strstr(t, "DIR");
        snprintf(words[argc], sizeof words[argc], "%.*s%s%s", d ? (int)(d - t) : (int)strlen(t), t, d ? dir : "",
                 d ? d + 3 : "");
        argv[argc] = words[argc];
        argc++;
    }
    argv[argc] = NULL;
    cr_assert(pipe(fd) == 0);
    pid_t pid = fork();
    cr_assert(pid >= 0);
    if (pid == 0) {
        dup2(fd[1], 2);
        close(fd[0]);
        if (!freopen("/dev/null", "w", stdout)) _exit(99);
        signal(SIGXFSZ, SIG_IGN); /* stays ignored across exec: writes fail with EFBIG instead */
        struct rlimit r = {(rlim_t)how.limit, RLIM_INFINITY};
        if (how.limit > 0 && setrlimit(RLIMIT_FSIZE, &r) != 0) _exit(97);
        if (how.fail) setenv("PSS_TEST_FAIL_WRITE", how.fail, 1);
        setenv("REPORT_DIR", dir, 1); /* scripts/report.sh's page */
        execvp(argv[0], argv);
        _exit(98);
    }
    close(fd[1]);
    if (how.sigint > 0) {
        nanosleep(&(struct timespec){(time_t)how.sigint, (long)((how.sigint - (time_t)how.sigint) * 1e9)}, NULL);
        kill(pid, SIGINT);
    }
    size_t got = 0;
    ssize_t k;
    while ((k = read(fd[0], err + got, n - 1 - got)) > 0)
        got += (size_t)k;
    err[got] = 0;
    close(fd[0]);
    int st;
    cr_assert_eq(waitpid(pid, &st, 0), pid);
    return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
}

static void good_run(const char *cmd)
{
    char err[8192];
    int st = run(cmd, (struct run){0}, err, sizeof err);
    cr_assert_eq(st, 0, "%s: status %d: %s", cmd, st, err);
}

/* A file's bytes and their count; the caller frees them. */
static char *slurp(const char *name, size_t *n)
{
    char p[256];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    FILE *f = fopen(p, "rb");
    cr_assert(f, "%s is missing", p);
    char *b = NULL;
    *n = 0;
    for (size_t cap = 0, k = 1; k > 0; *n += k) {
        b = realloc(b, cap += 1 << 16);
        k = fread(b + *n, 1, cap - *n, f);
    }
    fclose(f);
    return b;
}

static void expect_same(const char *name, const char *before, size_t n0)
{
    size_t n1;
    char *after = slurp(name, &n1);
    cr_expect(n0 == n1 && !memcmp(before, after, n0), "%s changed (%zu bytes, now %zu)", name, n0, n1);
    free(after);
}

/* Runs `cmd` after a good run of `good` (NULL: the caller made one) has written `name` (and `also`,
 * or NULL), and checks the failure: status, one stderr line naming `name`, both files' old bytes, no
 * temporary left. */
static void fails_cleanly(const char *good, const char *cmd, struct run how, const char *name, const char *also)
{
    if (good) good_run(good);
    size_t n0, n2 = 0;
    char *before = slurp(name, &n0), *other = also ? slurp(also, &n2) : NULL, err[8192], path[256];
    int st = run(cmd, how, err, sizeof err);
    snprintf(path, sizeof path, "%s/%s:", dir, name);
    cr_expect_eq(st, 1, "status %d, stderr: %s", st, err);
    size_t len = strlen(err);
    char *last = len ? err + len - 1 : err; /* the last line's start */
    while (last > err && last[-1] != '\n')
        last--;
    cr_expect(len && err[len - 1] == '\n' && (how.chatty || last == err), "not one line on stderr: '%s'", err);
    cr_expect(strstr(last, path) && strstr(last, "left as it was"), "the last line does not name %s: '%s'", path, err);
    cr_expect(strstr(err, "cannot") == strstr(last, "cannot"), "more than one error line: '%s'", err);
    expect_same(name, before, n0);
    if (also) expect_same(also, other, n2);
    free(before);
    free(other);
    DIR *d = opendir(dir);
    cr_assert(d);
    for (struct dirent *e; (e = readdir(d));)
        cr_expect(!strstr(e->d_name, ".tmp"), "temporary %s left in %s", e->d_name, dir);
    closedir(d);
}

#define RENDER BIN_DIR "/render scenes/cornell-box/scene.json --resolution 16x12 --quiet --out DIR/a"
#define MMLT RENDER " --method mmlt --spp 2 --seed-paths 2000 --angle-stats --technique-images 3 --mixing-image"
#define PT_CKPT RENDER " --method pt --spp 1024 --checkpoint 0.01"

Test(disk_full, render_exr_under_a_file_size_limit)
{
    fails_cleanly(RENDER " --method pt --spp 4", RENDER " --method pt --spp 4", (struct run){.limit = 512}, "a.exr",
                  NULL);
}

Test(disk_full, render_png_csv_angle_and_technique_outputs)
{
    const char *names[] = {"a.png",       "a.csv",         "a.mixing.exr", "a.mixing.csv",
                           "a.angle.exr", "a.tech-t2.exr", "a.tech.csv"};
    good_run(MMLT); /* a failing run changes nothing to redo */
    for (size_t i = 0; i < sizeof names / sizeof *names; i++)
        fails_cleanly(NULL, MMLT, (struct run){.fail = names[i]}, names[i], NULL);
}

Test(disk_full, checkpoint_during_the_run_stops_it)
{
    fails_cleanly(PT_CKPT, PT_CKPT, (struct run){.limit = 512}, "a.ckpt", "a.exr"); /* no outputs after it */
}

Test(disk_full, checkpoint_at_ctrl_c)
{
    fails_cleanly(PT_CKPT, RENDER " --method pt --spp 1000000", (struct run){.limit = 512, .sigint = 0.5}, "a.ckpt",
                  "a.exr");
}

#define FIG45                                                                                                          \
    BIN_DIR "/fig4_5 --scene scenes/cornell-box/scene.json --mutations 2000 --max-length 4 --threads 1 --out DIR"

Test(disk_full, experiment_csv)
{
    fails_cleanly(FIG45, FIG45, (struct run){.limit = 256, .chatty = true}, "fig4.5.csv", NULL);
}

/* a figure's table of its chains' mixing diagnostics (common/mixing_runs.h) */
Test(disk_full, experiment_mixing_csv)
{
    fails_cleanly(FIG45, FIG45, (struct run){.fail = "fig4.5-mixing.csv", .chatty = true}, "fig4.5-mixing.csv", NULL);
}

Test(disk_full, experiment_markdown)
{
    const char *cmd = BIN_DIR "/table1_cmlt --budgets 2k --seeds 2 --res 8 --ref-spp 4 --out DIR";
    fails_cleanly(cmd, cmd, (struct run){.fail = "table1.md", .chatty = true}, "table1.md", NULL);
}

/* what make's TO_FILE does with every figure's table */
Test(disk_full, figure_table_through_make)
{
    good_run(FIG45);
    const char *table = "bash scripts/to-file.sh make DIR/fig4.5.md bash scripts/fig4.5-table.sh DIR/fig4.5.csv";
    fails_cleanly(table, table, (struct run){.limit = 64}, "fig4.5.md", NULL);
}

Test(disk_full, report_page)
{
    fails_cleanly("bash scripts/report.sh", "bash scripts/report.sh", (struct run){.limit = 1024}, "index.html", NULL);
}

/* the figures' plots (the Makefile's GNUPLOT, scripts/plot.sh) and montages (scripts/ch4-montage.sh) */
Test(disk_full, plot_and_montage)
{
    good_run(FIG45);
    const char *plot = "bash scripts/plot.sh scripts/fig4.5.gp DIR/fig4.5.csv DIR/fig4.5";
    fails_cleanly(plot, plot, (struct run){.limit = 2048}, "fig4.5.png", "fig4.5.pdf");
    const char *montage = "bash scripts/ch4-montage.sh DIR/m.png 2 32x32 DIR/fig4.5.png a DIR/fig4.5.png b";
    fails_cleanly(montage, montage, (struct run){.limit = 2048, .chatty = true}, "m.png", NULL);
}
