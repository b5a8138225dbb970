/* Checkpoint and resume (core/io/checkpoint.h, bin/render --checkpoint/--resume): a run killed with
 * SIGKILL at random moments and resumed from its last checkpoint, or stopped with Ctrl-C and
 * resumed, ends with the same image bits and statistics as a run never stopped; a checkpoint from
 * another build, scene or options is refused, and a truncated or corrupted one is detected. */
#include <criterion/criterion.h>

#include "base/rng.h"
#include "io/checkpoint.h"
#include "io/image.h"
#include "support/tmpdir.h"
#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#ifndef BIN_DIR
#define BIN_DIR "bin"
#endif

static char dir[64];

static void make_dir(void) { tmpdir_make(dir, sizeof dir, "ckpt-test"); }
static void remove_dir(void) { tmpdir_remove(dir); }
TestSuite(checkpoint, .init = make_dir, .fini = remove_dir);

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* Milliseconds every checkpoint write of the next start() pauses halfway (0: none). */
static int stall_ms;

/* Starts bin/render with the words of `args` (space-separated) and `extra`, stdout and stderr to
 * DIR/stdout and DIR/stderr. */
static pid_t start(const char *args, const char *extra)
{
    char line[2048];
    snprintf(line, sizeof line, "%s %s --quiet", args, extra);
    char *argv[64];
    int argc = 0;
    argv[argc++] = BIN_DIR "/render";
    for (char *t = strtok(line, " "); t && argc < 63; t = strtok(NULL, " "))
        argv[argc++] = t;
    argv[argc] = NULL;
    pid_t pid = fork();
    cr_assert(pid >= 0);
    if (pid == 0) {
        char p[128];
        snprintf(p, sizeof p, "%s/stdout", dir);
        if (!freopen(p, "w", stdout)) _exit(99);
        snprintf(p, sizeof p, "%s/stderr", dir);
        if (!freopen(p, "w", stderr)) _exit(99);
        if (stall_ms) {
            snprintf(p, sizeof p, "%d", stall_ms);
            setenv("PSS_TEST_WRITE_STALL_MS", p, 1);
        }
        execv(argv[0], argv);
        _exit(98);
    }
    return pid;
}

static int finish(pid_t pid)
{
    int st;
    cr_assert_eq(waitpid(pid, &st, 0), pid);
    return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
}

static void path_of(char *p, size_t n, const char *name) { snprintf(p, n, "%s/%s", dir, name); }

static bool exists(const char *name)
{
    char p[256];
    path_of(p, sizeof p, name);
    return access(p, F_OK) == 0;
}

static void read_text(const char *name, char *buf, size_t n)
{
    char p[256];
    path_of(p, sizeof p, name);
    FILE *f = fopen(p, "r");
    size_t got = f ? fread(buf, 1, n - 1, f) : 0;
    buf[got] = 0;
    if (f) fclose(f);
}

/* The EXR's pixels bit for bit (the file's header holds a date). */
static void assert_same_pixels(const char *a, const char *b)
{
    char pa[256], pb[256], err[512];
    path_of(pa, sizeof pa, a);
    path_of(pb, sizeof pb, b);
    struct image *x = img_read(pa, err, sizeof err), *y = img_read(pb, err, sizeof err);
    cr_assert(x && y, "%s", err);
    cr_assert(x->w == y->w && x->h == y->h);
    cr_assert(!memcmp(x->px, y->px, 3 * sizeof(double) * (size_t)x->w * x->h), "%s and %s differ", a, b);
    img_destroy(x);
    img_destroy(y);
}

/* The CSV's statistics rows and counters; timings differ from run to run and are left out. */
static void assert_same_stats(const char *a, const char *b)
{
    static char x[1 << 16], y[1 << 16];
    read_text(a, x, sizeof x);
    read_text(b, y, sizeof y);
    cr_assert(x[0]);
    char *sx, *sy;
    char *lx = strtok_r(x, "\n", &sx), *ly = strtok_r(y, "\n", &sy);
    for (; lx && ly; lx = strtok_r(NULL, "\n", &sx), ly = strtok_r(NULL, "\n", &sy))
        if (!strstr(lx, "seconds") && !strstr(lx, "per_second")) cr_assert_str_eq(lx, ly);
    cr_assert(!lx && !ly, "%s and %s have different lengths", a, b);
}

/* The name of a temporary of DIR/run.ckpt (atomic_write's ".tmpPID-run.ckpt") into buf, or false. */
static bool find_temporary(char *buf, size_t n)
{
    DIR *d = opendir(dir);
    cr_assert(d);
    bool found = false;
    for (struct dirent *e; !found && (e = readdir(d));) {
        size_t l = strlen(e->d_name);
        if (!strncmp(e->d_name, ".tmp", 4) && l > 9 && !strcmp(e->d_name + l - 9, "-run.ckpt")) {
            snprintf(buf, n, "%s/%s", dir, e->d_name);
            found = true;
        }
    }
    closedir(d);
    return found;
}

/* Whether DIR/NAME is absent or a whole checkpoint: what a kill must leave. */
static bool absent_or_intact(const char *name)
{
    char p[256];
    path_of(p, sizeof p, name);
    return access(p, F_OK) != 0 || ckpt_file_intact(p);
}

/* The uninterrupted run of `args`, into DIR/ref; returns its wall time. The previous method's
 * checkpoint and temporary go first. */
static double reference_run(const char *args)
{
    char ref[2048], old[256];
    path_of(old, sizeof old, "run.ckpt");
    unlink(old);
    while (find_temporary(old, sizeof old))
        unlink(old);
    snprintf(ref, sizeof ref, "%s --out %s/ref", args, dir);
    double t0 = now();
    cr_assert_eq(finish(start(ref, "")), 0);
    return now() - t0;
}

/* The last start of a killed run: it must complete, leave no temporary, and end with the
 * uninterrupted run's pixels (and statistics rows for the MCMC methods). */
static void complete_and_compare(const char *run, const char *resume, bool mcmc)
{
    char err[1024];
    int st = finish(start(run, exists("run.ckpt") ? resume : ""));
    read_text("stderr", err, sizeof err);
    cr_assert_eq(st, 0, "%s", err);
    char tmp[512];
    cr_assert(!find_temporary(tmp, sizeof tmp), "a completed run left a temporary of its checkpoint: %s", tmp);
    assert_same_pixels("ref.exr", "run.exr");
    if (mcmc) assert_same_stats("ref.csv", "run.csv");
    if (mcmc) assert_same_stats("ref.mixing.csv", "run.mixing.csv"); /* the chains' traces are checkpointed */
}

/* One uninterrupted run, then the same run killed (SIGKILL) `kills` times at random moments, each
 * time resumed from its latest checkpoint (or restarted when none was written yet), and at last
 * completed. Checkpoints every 50 ms; the kill moments are drawn from a fixed-seed generator over
 * 10-50 % of the uninterrupted run's duration. A start that finishes before its kill (a resumed run
 * has less left to do, and a loaded machine stretches the start-up) ends that run, and its
 * checkpoint is removed so that the next start begins afresh; starts go on, up to three per wanted kill, until `kills`
 * kills have landed in a running render. When none of those starts continued from a checkpoint (a loaded machine
 * stretches the start-up and the seed pass, which write none, past every early kill), up to `kills` more starts are
 * killed later, at 50-90 %, until one has. After every kill the checkpoint is absent or whole. Returns how many starts
 * were killed while running; *resumed counts the starts that continued from a checkpoint. */
static int kill_and_resume(const char *args, bool mcmc, int kills, uint64_t seed, int *resumed, int *starts)
{
    char run[2048], resume[2048];
    double span = reference_run(args);
    snprintf(run, sizeof run, "%s --out %s/run --checkpoint 0.05", args, dir);
    snprintf(resume, sizeof resume, "--resume %s/run.ckpt", dir);
    rng r;
    rng_seed(&r, seed, 7);
    int killed = 0;
    *resumed = 0;
    int i = 0;
    for (; killed < kills ? i < 3 * kills : !*resumed && i < 4 * kills; i++) {
        bool from_ckpt = exists("run.ckpt"), extra = killed >= kills;
        *resumed += from_ckpt;
        pid_t pid = start(run, from_ckpt ? resume : "");
        usleep((useconds_t)(1e6 * ((extra ? 0.5 : 0.1) + 0.4 * rng_uniform(&r)) * span));
        kill(pid, SIGKILL);
        int st = finish(pid);
        cr_assert(absent_or_intact("run.ckpt"), "start %d left a torn checkpoint", i);
        if (st == 128 + SIGKILL) {
            killed++;
        } else { /* done before the kill: its last checkpoint would make every later start as short */
            char err[1024], ckpt[256];
            read_text("stderr", err, sizeof err);
            cr_assert_eq(st, 0, "start %d: %s", i, err);
            path_of(ckpt, sizeof ckpt, "run.ckpt");
            unlink(ckpt);
        }
    }
    *starts = i;
    complete_and_compare(run, resume, mcmc);
    return killed;
}

/* Kill points of the running test, for its log (each test runs in its own process). */
static int kill_points;

static void kills_of(const char *args, bool mcmc, int kills, uint64_t seed)
{
    int resumed, starts, killed = kill_and_resume(args, mcmc, kills, seed, &resumed, &starts);
    kill_points += killed;
    cr_log_info("%s: %d kills landed in a running render in %d starts, %d resumes from a checkpoint (%d kill points in "
                "this test)",
                args, killed, starts, resumed, kill_points);
    /* timing decides where the kills land: all must hit a running render within three starts per
     * kill, and one resume must start from a checkpoint (with up to `kills` later kills for it) */
    cr_assert_geq(killed, kills, "%s: only %d of %d kills hit a running render in %d starts", args, killed, kills,
                  starts);
    cr_assert_gt(resumed, 0, "%s", args);
}

#define COMMON "scenes/cornell-box/scene.json --resolution 48x36 --threads 2 --seed 4"
#define MCMC COMMON " --seed-paths 20000 --spp 300 --method "

/* Each method with a budget that takes the uninterrupted run about a second (more under the
 * sanitizers, and the kill moments scale with it): ten kills each of PT, BDPT, MMLT and PITP,
 * three of the other MCMC variants, 55 in all. */
Test(checkpoint, sigkill_and_resume_is_bit_identical_pt_bdpt, .timeout = 600)
{
    kills_of(COMMON " --method pt --spp 400", false, 10, 1);
    kills_of(COMMON " --method bdpt --spp 120", false, 10, 2);
}

Test(checkpoint, sigkill_and_resume_is_bit_identical_mmlt_pitp, .timeout = 600)
{
    kills_of(MCMC "mmlt --technique-images 3", true, 10, 10);
    assert_same_pixels("ref.tech-t2.exr", "run.tech-t2.exr");
    assert_same_pixels("ref.count-t3.exr", "run.count-t3.exr");
    assert_same_stats("ref.tech.csv", "run.tech.csv");
    kills_of(MCMC "pitp", true, 10, 11);
}

Test(checkpoint, sigkill_and_resume_is_bit_identical_other_mcmc, .timeout = 600)
{
    kills_of(MCMC "pssmlt --spp 100", true, 3, 12);
    kills_of(MCMC "pitp --small-step controlled --angle-stats", true, 3, 13);
    assert_same_pixels("ref.angle.exr", "run.angle.exr");
    kills_of(MCMC "mmlt --large-step hybrid --hybrid-length 3", true, 3, 14);
    kills_of(MCMC "mmlt --progressive-norm --seed-paths 3", true, 3, 15); /* length images; missed lengths */
    /* These two mutate fast: 300 mutations per pixel are 0.14 s of a 0.67 s run (start-up, seed pass and
     * output are the rest, and the seed pass is not checkpointed), so kills at 10-50 % of the run
     * could all land before the first checkpoint (a CI run saw it for --one-chain): longer chains. */
    kills_of(MCMC "mmlt --one-chain --spp 3000", true, 3, 16);
    kills_of(MCMC "mlt --spp 4000", true, 3, 17); /* Veach's path-space state (veach.c's checkpoint I/O) */
}

/* SIGKILL in the middle of a checkpoint write, three times per method: every write pauses 150 ms
 * halfway through its payload (PSS_TEST_WRITE_STALL_MS), and the kill comes 30 ms after the
 * temporary of a start's second write has appeared. The previous checkpoint must then be whole (or
 * absent before the first) and the torn temporary must not pass for one; the last, unstalled run
 * finds the torn temporaries of the killed processes beside the checkpoint, must remove them and
 * end bit-identical. */
static void kills_during_writes(const char *args, bool mcmc)
{
    char run[2048], resume[2048], tmp[1024], seen[3][1024];
    reference_run(args);
    snprintf(run, sizeof run, "%s --out %s/run --checkpoint 0.1", args, dir);
    snprintf(resume, sizeof resume, "--resume %s/run.ckpt", dir);
    stall_ms = 150;
    int kills = 0;
    for (int i = 0; i < 3; i++) {
        /* hide the previous kills' temporaries, so that the next one to appear is this start's */
        for (int k = 0; k < i; k++) {
            char hidden[1100];
            snprintf(hidden, sizeof hidden, "%.1000s.hidden", seen[k]);
            rename(seen[k], hidden);
        }
        pid_t pid = start(run, exists("run.ckpt") ? resume : "");
        /* one write completes (its temporary appears, then is renamed away), so that each start
         * makes progress; the kill lands in the next */
        bool ended = false;
        int st = 0;
        for (int phase = 0; phase < 3 && !ended; phase++) {
            bool want = phase != 1;
            double t0 = now();
            while (find_temporary(tmp, sizeof tmp) != want && now() - t0 < 60 && !ended) {
                usleep(2000);
                ended = waitpid(pid, &st, WNOHANG) == pid; /* a loaded or fast machine: the run was done first */
            }
            cr_assert(ended || find_temporary(tmp, sizeof tmp) == want, "%s: checkpoint writes stopped (phase %d)",
                      args, phase);
        }
        if (!ended) {
            usleep(30000); /* well inside the 150 ms pause */
            kill(pid, SIGKILL);
            st = finish(pid);
            ended = st != 128 + SIGKILL;
        }
        if (ended) { /* no kill this round: the run completed (or died otherwise, which the end shows) */
            for (int k = 0; k < i; k++) {
                char hidden[1100];
                snprintf(hidden, sizeof hidden, "%.1000s.hidden", seen[k]);
                rename(hidden, seen[k]);
            }
            break;
        }
        kills++;
        kill_points++;
        cr_assert(absent_or_intact("run.ckpt"), "%s: a kill during a write tore the checkpoint", args);
        cr_assert(!ckpt_file_intact(tmp), "%s: the half-written temporary passes for a checkpoint", args);
        snprintf(seen[i], sizeof seen[i], "%s", tmp);
        for (int k = 0; k < i; k++) {
            char hidden[1100];
            snprintf(hidden, sizeof hidden, "%.1000s.hidden", seen[k]);
            rename(hidden, seen[k]);
        }
    }
    stall_ms = 0;
    cr_assert_gt(kills, 0, "%s: no kill landed inside a checkpoint write", args);
    complete_and_compare(run, resume, mcmc);
    cr_log_info("%s: %d kills during checkpoint writes (%d kill points in this test)", args, kills, kill_points);
}

Test(checkpoint, sigkill_during_a_checkpoint_write_leaves_the_previous_one, .timeout = 600)
{
    /* ten times the budgets of the random kills: every start must reach a second checkpoint write
     * before it ends, also in a PGO build on a loaded machine */
    kills_during_writes(COMMON " --method pt --spp 4000", false);
    kills_during_writes(COMMON " --method bdpt --spp 1200", false);
    kills_during_writes(MCMC "mmlt --spp 1500", true);
    kills_during_writes(MCMC "pitp --spp 1500", true);
}

/* Ctrl-C keeps its behaviour (the partial image, exit status 130) and leaves a checkpoint that
 * resumes to the uninterrupted result. The signal comes at 60 % of the uninterrupted run's time
 * (earlier if the run was already over). */
Test(checkpoint, ctrl_c_leaves_a_resumable_checkpoint, .timeout = 300)
{
    const char *args = COMMON " --method mmlt --seed-paths 20000 --spp 600";
    char ref[1024], run[1024], resume[512], err[1024];
    snprintf(ref, sizeof ref, "%s --out %s/ref", args, dir);
    double t0 = now();
    cr_assert_eq(finish(start(ref, "")), 0);
    double span = now() - t0;
    snprintf(run, sizeof run, "%s --out %s/run", args, dir);
    /* a loaded machine can make the first run slower than this one: then the signal comes too
     * late, and it is sent earlier */
    int st = 0;
    for (double at = 0.6; st == 0 && at > 0.01; at /= 2) {
        pid_t pid = start(run, "");
        usleep((useconds_t)(1e6 * at * span));
        kill(pid, SIGINT);
        st = finish(pid);
    }
    read_text("stderr", err, sizeof err);
    cr_assert_eq(st, 130, "exit %d: %s", st, err);
    cr_assert(exists("run.exr") && exists("run.ckpt"));
    cr_assert(strstr(err, "--resume"), "%s", err);
    snprintf(resume, sizeof resume, "--resume %s/run.ckpt", dir);
    cr_assert_eq(finish(start(run, resume)), 0);
    assert_same_pixels("ref.exr", "run.exr");
    assert_same_stats("ref.csv", "run.csv");
}

static int lines(const char *s)
{
    int n = 0;
    for (; *s; s++)
        n += *s == '\n';
    return n;
}

/* Resuming refuses, with one line and exit status 2 that names the option: other options (another
 * thread count among them; another rank count is tests/mpi's), another scene, a corrupted or
 * truncated file. */
Test(checkpoint, refuses_other_options_scene_and_damaged_files, .timeout = 300)
{
    char cmd[1024], resume[512], err[1024], path[256];
    snprintf(cmd, sizeof cmd, "%s --out %s/run --spp 100000", COMMON " --method pt", dir);
    pid_t pid = start(cmd, "");
    usleep(500000);
    kill(pid, SIGINT);
    cr_assert_eq(finish(pid), 130);
    cr_assert(exists("run.ckpt"));
    snprintf(resume, sizeof resume, "--resume %s/run.ckpt", dir);
    const struct {
        const char *args, *says;
    } cases[] = {
        {COMMON " --method pt --spp 99999", "other options: spp=100000 (this run: spp=99999)"},
        {COMMON " --method bdpt --spp 100000", "other options: method=pt (this run: method=bdpt)"},
        {"scenes/cornell-box/scene.json --resolution 48x36 --threads 1 --seed 4 --method pt --spp 100000",
         "other options: threads=2 (this run: threads=1)"},
        {"scenes/furnace/scene.json --resolution 48x36 --threads 2 --seed 4 --method pt --spp 100000", "another scene"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        snprintf(cmd, sizeof cmd, "%s --out %s/other", cases[i].args, dir);
        cr_assert_eq(finish(start(cmd, resume)), 2, "%s", cases[i].args);
        read_text("stderr", err, sizeof err);
        cr_assert(strstr(err, cases[i].says) && lines(err) == 1, "%s: %s", cases[i].args, err);
        cr_assert(!exists("other.exr"));
    }
    /* one byte flipped in the middle, then the file cut short */
    path_of(path, sizeof path, "run.ckpt");
    struct stat sb;
    cr_assert_eq(stat(path, &sb), 0);
    FILE *f = fopen(path, "r+b");
    cr_assert(f);
    fseek(f, sb.st_size / 2, SEEK_SET);
    int c = fgetc(f);
    fseek(f, sb.st_size / 2, SEEK_SET);
    fputc(c ^ 0x10, f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "%s --out %s/other --spp 100000", COMMON " --method pt", dir);
    for (int pass = 0; pass < 2; pass++) {
        cr_assert_eq(finish(start(cmd, resume)), 2);
        read_text("stderr", err, sizeof err);
        cr_assert(strstr(err, "truncated or corrupted") && lines(err) == 1, "%s", err);
        cr_assert(!exists("other.exr"));
        cr_assert_eq(truncate(path, sb.st_size - 1000), 0);
    }
}

/* The file format in-process: a round trip, and a checkpoint of another build refused by name. */
Test(checkpoint, file_round_trip_and_build_check)
{
    struct ckpt_buf p = {0}, q;
    for (int i = 0; i < 1000; i++)
        CKPT_PUT(&p, i);
    char path[256], err[512];
    path_of(path, sizeof path, "x.ckpt");
    struct ckpt_id id = {42, 7, "method=pt spp=1"}, other = id;
    cr_assert(ckpt_write_file(path, &id, &p, err, sizeof err), "%s", err);
    cr_assert(ckpt_read_file(path, &id, &q, err, sizeof err), "%s", err);
    cr_assert(q.len == p.len && !memcmp(q.p, p.p, p.len));
    int v;
    for (int i = 0; i < 1000; i++)
        cr_assert(CKPT_GET(&q, v) && v == i);
    cr_assert(!CKPT_GET(&q, v) && q.short_read, "a read past the end is reported");
    ckpt_buf_free(&q);
    other.build = 43;
    cr_assert(!ckpt_read_file(path, &other, &q, err, sizeof err));
    cr_assert(strstr(err, "another build"), "%s", err);
    cr_assert_eq(q.len, 0u);
    ckpt_buf_free(&p);
}
