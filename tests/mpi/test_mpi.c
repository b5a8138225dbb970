/* bin/render under mpirun (make test-mpi; README "MPI: paper-scale runs"): N ranks x T threads give
 * the same bits as one process of N x T threads for every method, the furnace's exact answer, one
 * error line for bad input, a refusal from the tools that are not rank-aware, and a job that fails,
 * not hangs, when a rank is killed. Every job is oversubscribed on one machine. */
#include <criterion/criterion.h>

#include "base/util.h"
#include "io/checkpoint.h"
#include "io/image.h"
#include <ctype.h>
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

/* A job that takes longer than this has hung. */
#define JOB_TIMEOUT "120"

static char dir[64];

/* mpirun refuses root without the first two (CI runs as root). Shared-memory transfers between
 * ranks use cross-memory attach by default, which containers without ptrace rights refuse mid-run;
 * copying through the shared segment costs nothing at these image sizes. Set here too so that the
 * runner works when started by hand, not only through make test-mpi. */
static void setup(void)
{
    setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 0);
    setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 0);
    setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", 0);
    snprintf(dir, sizeof dir, "/tmp/mpi-test-XXXXXX");
    cr_assert(mkdtemp(dir));
}

static void teardown(void)
{
    if (!dir[0]) return;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
}

TestSuite(mpi, .init = setup, .fini = teardown, .timeout = 170);

/* Runs bin/render (ranks = 0: directly, without mpirun) with its output in dir/NAME.out and
 * dir/NAME.err; returns the exit status. */
static int run_render(int ranks, const char *name, const char *args)
{
    char cmd[2048], launcher[128] = "";
    if (ranks > 0) snprintf(launcher, sizeof launcher, "mpirun --oversubscribe -np %d ", ranks);
    snprintf(cmd, sizeof cmd,
             "timeout " JOB_TIMEOUT " %s" BIN_DIR "/render %s --quiet --out %s/%s >%s/%s.out 2>%s/%s.err", launcher,
             args, dir, name, dir, name, dir, name);
    int rc = system(cmd);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : 128 + WTERMSIG(rc);
}

static char *output(const char *name, const char *ext)
{
    char p[256];
    snprintf(p, sizeof p, "%s/%s.%s", dir, name, ext);
    return read_whole_file(p);
}

/* The same pixels, bit for bit (the files' bytes differ: OpenImageIO stamps the time of writing). */
static bool same_pixels(const char *a, const char *b, const char *ext)
{
    char pa[256], pb[256], err[256];
    snprintf(pa, sizeof pa, "%s/%s.%s", dir, a, ext);
    snprintf(pb, sizeof pb, "%s/%s.%s", dir, b, ext);
    struct image *ia = img_read(pa, err, sizeof err), *ib = img_read(pb, err, sizeof err);
    cr_assert(ia && ib, "%s", err);
    bool same = ia->w == ib->w && ia->h == ib->h && !memcmp(ia->px, ib->px, (size_t)ia->w * ia->h * 3 * sizeof *ia->px);
    img_destroy(ia);
    img_destroy(ib);
    return same;
}

/* A statistics CSV without the lines that legitimately differ: times, rates and the thread layout. */
static char *csv_body(const char *name, const char *ext)
{
    char *s = output(name, ext);
    cr_assert(s, "%s.%s missing", name, ext);
    static const char *skip[] = {"# seconds", "# seed_seconds", "# mutations_per_second", "# threads", "# ranks", NULL};
    char *out = calloc(strlen(s) + 1, 1), *o = out;
    for (char *line = s; *line;) {
        char *end = strchr(line, '\n');
        size_t n = end ? (size_t)(end - line + 1) : strlen(line);
        bool keep = true;
        for (const char **k = skip; *k; k++)
            if (!strncmp(line, *k, strlen(*k)) && (line[strlen(*k)] == ' ' || line[strlen(*k)] == '\n')) keep = false;
        if (keep) {
            memcpy(o, line, n);
            o += n;
        }
        line += n;
    }
    free(s);
    return out;
}

static const char *box = "scenes/cornell-box/scene.json --resolution 40x30 --max-length 6 --seed 7";

/* One process of 6 threads, then 2 ranks x 3 and 3 ranks x 2: the same EXR bytes and, for the
 * MCMC methods, the same statistics (and angle statistics with `angle`). */
static void same_bits(const char *method, const char *budget, bool mcmc, bool angle)
{
    char args[512];
    const struct {
        const char *name;
        int ranks, threads;
    } runs[] = {{"single", 0, 6}, {"np2", 2, 3}, {"np3", 3, 2}};
    for (int i = 0; i < 3; i++) {
        snprintf(args, sizeof args, "%s --method %s %s --threads %d%s%s", box, method, budget, runs[i].threads,
                 angle ? " --angle-stats" : "", mcmc ? " --mixing-image" : "");
        int rc = run_render(runs[i].ranks, runs[i].name, args);
        char *err = output(runs[i].name, "err");
        cr_assert_eq(rc, 0, "%s: exit %d: %s", runs[i].name, rc, err);
        free(err);
    }
    for (int i = 1; i < 3; i++) {
        cr_expect(same_pixels("single", runs[i].name, "exr"), "%s: %s.exr differs from one process's", method,
                  runs[i].name);
        if (mcmc) {
            char *a = csv_body("single", "csv"), *b = csv_body(runs[i].name, "csv");
            cr_expect_str_eq(a, b, "%s: %s.csv differs from one process's", method, runs[i].name);
            free(a);
            free(b);
            /* the chains' mixing records, gathered over the ranks in global thread order */
            a = csv_body("single", "mixing.csv");
            b = csv_body(runs[i].name, "mixing.csv");
            cr_expect_str_eq(a, b, "%s: %s.mixing.csv differs from one process's", method, runs[i].name);
            free(a);
            free(b);
            /* the per-pixel counts, summed over the ranks like the image */
            cr_expect(same_pixels("single", runs[i].name, "mixing.exr"), "%s: %s.mixing.exr differs", method,
                      runs[i].name);
        }
        if (angle) {
            cr_expect(same_pixels("single", runs[i].name, "angle.exr"), "%s: %s.angle.exr differs", method,
                      runs[i].name);
            char *a = csv_body("single", "angle.csv"), *b = csv_body(runs[i].name, "angle.csv");
            cr_expect_str_eq(a, b, "%s: %s.angle.csv differs", method, runs[i].name);
            free(a);
            free(b);
        }
    }
    /* rank 0 alone prints the summary */
    char *out = output("np3", "out");
    int lines = 0;
    for (char *p = out; *p; p++)
        lines += *p == '\n';
    cr_expect_eq(lines, 1, "expected one summary line from 3 ranks, got:\n%s", out);
    cr_expect(strstr(out, "3 ranks x 2 threads"), "summary: %s", out);
    free(out);
}

Test(mpi, same_bits_pt) { same_bits("pt", "--spp 8", false, false); }
Test(mpi, same_bits_bdpt) { same_bits("bdpt", "--spp 4", false, false); }
Test(mpi, same_bits_pssmlt) { same_bits("pssmlt", "--spp 16 --seed-paths 4000", true, false); }
Test(mpi, same_bits_mmlt_with_angle_stats) { same_bits("mmlt", "--spp 16 --seed-paths 4000", true, true); }
Test(mpi, same_bits_pitp) { same_bits("pitp", "--spp 16 --seed-paths 4000", true, false); }

/* Mean of the image's channels; the furnace is grey. */
static double mean_value(const char *name)
{
    char p[256], err[256];
    snprintf(p, sizeof p, "%s/%s.exr", dir, name);
    struct image *im = img_read(p, err, sizeof err);
    cr_assert(im, "%s", err);
    double s = 0;
    size_t n = (size_t)im->w * im->h * 3;
    for (size_t i = 0; i < n; i++)
        s += im->px[i];
    img_destroy(im);
    return s / n;
}

/* scenes/furnace: albedo 0.5, Le 0.5 on every wall, so lengths <= K give Le (1 - a^K) / (1 - a)
 * everywhere (tests/test_render.c). 3 ranks: PT on a time budget (rank 0's pass decisions), BDPT
 * and MMLT on sample budgets; each within 1 %. */
Test(mpi, furnace_exact_on_3_ranks)
{
    const double exact = 0.5 * (1 - pow(0.5, 6)) / (1 - 0.5);
    const char *cases[][2] = {{"pt", "--time 1"}, {"bdpt", "--spp 4"}, {"mmlt", "--spp 64 --seed-paths 20000"}};
    for (int i = 0; i < 3; i++) {
        char args[512];
        snprintf(args, sizeof args,
                 "scenes/furnace/scene.json --resolution 64x64 --max-length 6 --threads 1 --method %s %s", cases[i][0],
                 cases[i][1]);
        int rc = run_render(3, cases[i][0], args);
        char *err = output(cases[i][0], "err");
        cr_assert_eq(rc, 0, "%s: exit %d: %s", cases[i][0], rc, err);
        free(err);
        double v = mean_value(cases[i][0]);
        cr_expect(fabs(v / exact - 1) < 0.01, "%s on 3 ranks: %g vs exact %g", cases[i][0], v, exact);
    }
}

static int count(const char *s, const char *sub)
{
    int n = 0;
    for (const char *p = s; (p = strstr(p, sub)); p++)
        n++;
    return n;
}

/* Every rank finds the bad input; rank 0 alone says so, once, and the job exits 2. */
Test(mpi, bad_input_one_line_exit_2)
{
    int rc = run_render(2, "bad", "tests/data/no-such-scene.json");
    char *err = output("bad", "err");
    cr_expect_eq(rc, 2, "exit %d: %s", rc, err);
    cr_expect_eq(count(err, "no-such-scene.json"), 1, "expected the error once:\n%s", err);
    free(err);
    rc = run_render(3, "badopt", "scenes/cornell-box/scene.json --spp 0");
    err = output("badopt", "err");
    cr_expect_eq(rc, 2, "exit %d: %s", rc, err);
    cr_expect_eq(count(err, "--spp"), 1, "expected the error once:\n%s", err);
    free(err);
}

/* A tool that does not split its work refuses mpirun with one line: bin/bench at its first render,
 * bin/ch6_equal (one process running its renders in turn) at once. */
Test(mpi, tools_not_rank_aware_refuse)
{
    const char *tools[] = {BIN_DIR "/bench --runs 1 --seconds 0.05",
                           BIN_DIR "/ch6_equal --scene scenes/cornell-box/scene.json"};
    for (int i = 0; i < 2; i++) {
        char cmd[512], p[128];
        snprintf(cmd, sizeof cmd, "timeout " JOB_TIMEOUT " mpirun --oversubscribe -np 2 %s >%s/tool.out 2>%s/tool.err",
                 tools[i], dir, dir);
        int rc = system(cmd);
        snprintf(p, sizeof p, "%s/tool.err", dir);
        char *err = read_whole_file(p);
        cr_expect(WIFEXITED(rc) && WEXITSTATUS(rc) == 2, "%s: status %d: %s", tools[i], rc, err);
        cr_expect_eq(count(err, "not rank-aware"), 1, "%s: expected the refusal once:\n%s", tools[i], err);
        free(err);
    }
}

/* The pid of the process run by mpirun `launcher` as rank `rank`, or 0. */
static pid_t find_rank(pid_t launcher, int rank)
{
    DIR *d = opendir("/proc");
    if (!d) return 0;
    char want[64];
    snprintf(want, sizeof want, "OMPI_COMM_WORLD_RANK=%d", rank);
    pid_t found = 0;
    for (struct dirent *e; !found && (e = readdir(d));) {
        if (!isdigit((unsigned char)e->d_name[0])) continue;
        char p[300];
        snprintf(p, sizeof p, "/proc/%s/stat", e->d_name);
        FILE *f = fopen(p, "r");
        if (!f) continue;
        int pid, ppid;
        char state;
        char comm[256];
        bool child = fscanf(f, "%d (%255[^)]) %c %d", &pid, comm, &state, &ppid) == 4 && ppid == launcher;
        fclose(f);
        if (!child) continue;
        snprintf(p, sizeof p, "/proc/%s/environ", e->d_name);
        f = fopen(p, "rb");
        if (!f) continue;
        char buf[1 << 15];
        size_t n = fread(buf, 1, sizeof buf - 1, f);
        fclose(f);
        buf[n] = 0;
        for (size_t i = 0; i < n; i += strlen(buf + i) + 1)
            if (!strcmp(buf + i, want)) found = pid;
    }
    closedir(d);
    return found;
}

static double seconds_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* Waits up to 30 s for rank `rank` of the mpirun job to appear; its pid. */
static pid_t wait_rank(pid_t job, int rank)
{
    pid_t victim = 0;
    double t0 = seconds_now();
    while (!victim && seconds_now() - t0 < 30) {
        usleep(20000);
        victim = find_rank(job, rank);
    }
    cr_assert(victim, "rank %d of the job never appeared", rank);
    return victim;
}

/* Kills rank `rank` (its pid `victim`) with SIGKILL, then asserts that mpirun ends the job within
 * 30 s, with a non-zero status and a message naming the signal (stderr in the file `err`). With
 * may_finish, a job that completed before the kill landed is no failure: returns false then. */
static bool kill_rank_and_wait(pid_t job, pid_t victim, int rank, const char *err, bool may_finish)
{
    kill(victim, SIGKILL);
    int status = 0;
    double t0 = seconds_now();
    while (waitpid(job, &status, WNOHANG) == 0) {
        if (seconds_now() - t0 > 30) {
            kill(job, SIGKILL);
            waitpid(job, &status, 0);
            cr_assert_fail("the job still ran 30 s after rank %d was killed", rank);
        }
        usleep(20000);
    }
    if (may_finish && WIFEXITED(status) && WEXITSTATUS(status) == 0) return false;
    char *msg = read_whole_file(err);
    cr_assert(!(WIFEXITED(status) && WEXITSTATUS(status) == 0), "the job succeeded without rank %d (killed too late?)",
              rank);
    cr_expect(strstr(msg, "signal 9") || strstr(msg, "Killed"), "mpirun did not say which rank died:\n%s", msg);
    free(msg);
    return true;
}

/* kill -9 of rank 1 mid-render: mpirun ends the job with a non-zero status and says which rank
 * died, within 30 s. */
Test(mpi, killed_rank_fails_the_job)
{
    char out[128], err[128];
    snprintf(out, sizeof out, "%s/kill.out", dir);
    snprintf(err, sizeof err, "%s/kill.err", dir);
    pid_t job = fork();
    cr_assert(job >= 0);
    if (job == 0) {
        if (!freopen(out, "w", stdout) || !freopen(err, "w", stderr)) _exit(127);
        execlp("mpirun", "mpirun", "--oversubscribe", "-np", "2", BIN_DIR "/render", "scenes/cornell-box/scene.json",
               "--method", "pt", "--spp", "100000", "--threads", "1", "--quiet", "--out", dir, (char *)NULL);
        _exit(127);
    }
    pid_t victim = wait_rank(job, 1);
    usleep(1500000); /* mid-render: well past MPI start-up and the scene's load */
    kill_rank_and_wait(job, victim, 1, err, false);
}

/* Checkpoints over ranks: each rank keeps its own threads' state in PREFIX.ckpt.rankR. A job of
 * 2 ranks x 2 threads stopped with SIGTERM to mpirun (which takes its ranks down) at three moments
 * over 20-80 % of an uninterrupted run's time, each time resumed from the ranks' latest 50 ms
 * checkpoints, then completed, gives the bits of one process of 4 threads. A resume with another
 * rank count is refused with one line. */
static void resumed_over_ranks(const char *name, const char *args)
{
    char a[1024], cmd[2048], ck[256];
    snprintf(a, sizeof a, "%s %s --threads 4", box, args);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    cr_assert_eq(run_render(0, "ref", a), 0);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double span = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    snprintf(ck, sizeof ck, "%s/run.ckpt.rank1", dir);
    unlink(ck);
    snprintf(ck, sizeof ck, "%s/run.ckpt.rank0", dir);
    unlink(ck);
    int resumed = 0;
    for (int i = 0; i <= 3; i++) {
        bool from = access(ck, F_OK) == 0;
        resumed += from;
        char stop[64] = "", resume[300] = "";
        if (i < 3) snprintf(stop, sizeof stop, "timeout -s TERM %.3f ", (0.2 + 0.2 * i) * span + 0.5);
        if (from) snprintf(resume, sizeof resume, "--resume %s/run.ckpt", dir);
        snprintf(cmd, sizeof cmd,
                 "%smpirun --oversubscribe -np 2 " BIN_DIR
                 "/render %s %s --threads 2 --checkpoint 0.05 %s --quiet --out %s/run "
                 ">%s/run.out 2>%s/run.err",
                 stop, box, args, resume, dir, dir, dir);
        int rc = system(cmd);
        if (i == 3) {
            char *err = output("run", "err");
            cr_assert(WIFEXITED(rc) && WEXITSTATUS(rc) == 0, "%s: final resume: %s", name, err);
            free(err);
        }
    }
    cr_expect_gt(resumed, 0, "%s: no resume started from a checkpoint", name);
    cr_expect(same_pixels("ref", "run", "exr"), "%s: resumed 2 x 2 differs from one process of 4 threads", name);
    /* 3 ranks cannot resume 2 ranks' checkpoints */
    snprintf(a, sizeof a, "%s %s --threads 2 --resume %s/run.ckpt", box, args, dir);
    cr_assert_eq(run_render(3, "three", a), 2);
    char *err = output("three", "err");
    cr_expect(count(err, "render: --resume") == 1, "%s", err);
    free(err);
}

Test(mpi, checkpoints_resume_over_ranks_bit_identical)
{
    resumed_over_ranks("mmlt", "--method mmlt --spp 800 --seed-paths 4000");
    resumed_over_ranks("pt", "--method pt --spp 1500");
}

/* Whether the file exists and was modified at or after t. */
static bool newer_than(const char *path, struct timespec t)
{
    struct stat sb;
    if (stat(path, &sb) != 0) return false;
    return sb.st_mtim.tv_sec > t.tv_sec || (sb.st_mtim.tv_sec == t.tv_sec && sb.st_mtim.tv_nsec >= t.tv_nsec);
}

/* SIGKILL of one rank of a checkpointing job, twice, each a tenth of an uninterrupted run's time
 * after that rank has written a checkpoint: mpirun ends the job and says which rank died, each
 * rank's checkpoint file is whole (a kill can tear only a temporary), and 2 ranks resuming from the
 * files that are there, then completing, give the bits of one process of 4 threads. Each rank's work is its own (its
 * seeds, its share of the pixels or chains), so each resumes from its own latest complete file: the set the job resumes
 * from is every rank's last complete checkpoint. */
static void rank_killed_and_resumed(const char *args, int victim_rank)
{
    char a[1024], ck[2][256], out[256], err[256], prefix[256], resume[300] = "";
    snprintf(a, sizeof a, "%s %s --threads 4", box, args);
    double t0 = seconds_now();
    cr_assert_eq(run_render(0, "ref", a), 0);
    double span = seconds_now() - t0;
    for (int r = 0; r < 2; r++) {
        snprintf(ck[r], sizeof ck[r], "%s/kr.ckpt.rank%d", dir, r);
        unlink(ck[r]);
    }
    snprintf(out, sizeof out, "%s/kr.exr", dir);
    unlink(out); /* an earlier call's image */
    snprintf(out, sizeof out, "%s/kr.out", dir);
    snprintf(err, sizeof err, "%s/kr.err", dir);
    snprintf(prefix, sizeof prefix, "%s/kr", dir);
    for (int kill_no = 0; kill_no < 2; kill_no++) {
        struct timespec started;
        clock_gettime(CLOCK_REALTIME, &started);
        pid_t job = fork();
        cr_assert(job >= 0);
        if (job == 0) {
            if (!freopen(out, "w", stdout) || !freopen(err, "w", stderr)) _exit(127);
            char *argv[64];
            int argc = 0;
            argv[argc++] = "mpirun", argv[argc++] = "--oversubscribe", argv[argc++] = "-np", argv[argc++] = "2";
            argv[argc++] = BIN_DIR "/render";
            char words[2048];
            snprintf(words, sizeof words, "%s %s --threads 2 --checkpoint 0.05 --quiet --out %s %s", box, args, prefix,
                     resume);
            for (char *t = strtok(words, " "); t && argc < 63; t = strtok(NULL, " "))
                argv[argc++] = t;
            argv[argc] = NULL;
            execvp("mpirun", argv);
            _exit(127);
        }
        pid_t victim = wait_rank(job, victim_rank);
        /* the kill comes a tenth of the run after the victim has written a checkpoint in this job,
         * so that it makes progress whatever MPI's start-up costs (the other rank may be done) */
        double t1 = seconds_now();
        while (!newer_than(ck[victim_rank], started) && seconds_now() - t1 < 30)
            usleep(5000);
        usleep((useconds_t)(1e6 * 0.1 * span));
        /* a resumed job has only what is left to do: on a fast machine it may end before the
         * second kill lands, and then its image is the resumed result (a fresh-clone CI run) */
        if (!kill_rank_and_wait(job, victim, victim_rank, err, kill_no > 0)) {
            fprintf(stderr, "mpi: %s: the resumed job finished before kill %d landed; its image is compared\n", args,
                    kill_no + 1);
            snprintf(a, sizeof a, "%s/kr.exr", dir);
            cr_assert(access(a, F_OK) == 0, "%s: the resumed job succeeded without an image", args);
            cr_expect(same_pixels("ref", "kr", "exr"),
                      "%s: killed and resumed 2 x 2 differs from one process of 4 threads", args);
            return;
        }
        for (int r = 0; r < 2; r++)
            cr_assert(access(ck[r], F_OK) != 0 || ckpt_file_intact(ck[r]), "%s: rank %d's checkpoint is torn", args, r);
        cr_assert(access(ck[0], F_OK) == 0 && access(ck[1], F_OK) == 0, "%s: a rank wrote no checkpoint", args);
        snprintf(resume, sizeof resume, "--resume %s/kr.ckpt", dir);
    }
    snprintf(a, sizeof a, "%s %s --threads 2 --checkpoint 0.05 %s", box, args, resume);
    int rc = run_render(2, "kr", a);
    char *e = output("kr", "err");
    cr_assert_eq(rc, 0, "%s: final resume: %s", args, e);
    free(e);
    cr_expect(same_pixels("ref", "kr", "exr"), "%s: killed and resumed 2 x 2 differs from one process of 4 threads",
              args);
}

Test(mpi, sigkill_of_one_rank_resumes_bit_identical)
{
    rank_killed_and_resumed("--method pt --spp 1500", 1);
    rank_killed_and_resumed("--method mmlt --spp 1600 --seed-paths 4000", 0);
}
