/* bin/ch6_equal: equal-time comparisons of MCMC methods on one scene (thesis chapter 6, Figures
 * 6.2-6.7; the MMLT paper's §5 non-zero ratio; the hybrid-MCTLS study). Every run is a bin/render
 * process, so any method bin/render accepts can be listed; a method it does not accept (probed with
 * `bin/render --method M --help`) is skipped and named in the outputs.
 *
 * For each seed 1..N, budget t0, 2 t0, ..., T seconds and method, in that order (interleaved): a
 * separate render with that seed and a --cpu-time budget (--wall-clock: --time) (the core has no snapshot facility; the
 * doubling budgets are separate runs, not snapshots of one run). Each image is compared with a BDPT reference rendered
 * once and cached: relMSE = mean over pixels and channels of (I - R)^2 / (R^2 + 0.01 m^2), m the reference's mean
 * luminance (the relMSE of both images scaled to a mean of 1, so a dark scene is not all epsilon);
 * PNGs are exposed by 0.5 / m. The spread of the per-block
 * relMSE over B x B blocks (coefficient of variation: 0 = uniform error); mutations/s and the fraction
 * of proposals with non-zero contribution from the render's statistics CSV.
 * With --spp the budget is a number of mutations per pixel instead (one run per seed and method):
 * statistics that do not depend on the machine, which make check-fig6.N compares with a baseline.
 * With --reference-spp 0 there is no reference (the image statistics are nan): only the counts of
 * the render CSVs, for the non-zero ratios.
 * Writes OUT/runs.csv (one row per run), OUT/summary.csv (mean +- standard error over seeds per method
 * and budget), OUT/stats.csv (the same at the largest budget, one row per method and statistic),
 * OUT/NAME.md (the table and the claims), OUT/reference.png and OUT/<method>.png (first seed, budget
 * T); all atomically. */
#include "base/dist.h"
#include "base/util.h"
#include "ch6/ch6_claims.h"
#include "ch6/ch6_stats.h"
#include "common/csv_meta.h"
#include "common/opts.h"
#include "io/image.h"
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#define MAX_METHODS 16
#define MAX_BUDGETS 16
#define MAX_SEEDS 64
#define MAX_ARGS 64

struct method {
    char name[64];
    char *argv[MAX_ARGS];
    int argc;
    bool available;
};

struct run {
    double seconds, q[Q_COUNT];
};

static char *split_args(char *s, char **argv, int *argc, int cap)
{
    for (char *tok = strtok(s, " "); tok; tok = strtok(NULL, " "))
        if (*argc < cap) argv[(*argc)++] = tok;
    return s;
}

/* Runs argv (NULL-terminated) with stdout and stderr to `log` (NULL: /dev/null); returns the exit status. */
static int run_cmd(char *const *argv, const char *log)
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

/* A cached file older than the scene it was rendered from is stale. */
static bool older_than(const char *a, const char *b)
{
    struct stat sa, sb;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_mtime < sb.st_mtime;
}

/* Runs the render rv[0..c-1] (rv has room for 5 more) into PREFIX with --checkpoint every `every`
 * seconds (0: none), resuming from PREFIX.ckpt when an interrupted earlier run left one; a
 * checkpoint the render refuses (other options) is set aside and the run starts over. */
static int run_checkpointed(char **rv, int c, const char *prefix, double every, const char *log)
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
        int st = run_cmd(rv, log);
        if (st == 0) unlink(ck);
        if (st != 2) return st;
        fprintf(stderr, "ch6_equal: %s was not resumable (see %s); starting over\n", ck, log ? log : "its log");
        unlink(ck);
    }
    rv[c] = NULL;
    int st = run_cmd(rv, log);
    if (st == 0 && every > 0) unlink(ck); /* complete: its outputs are what a rerun keeps */
    return st;
}

/* A run of an earlier, interrupted ch6_equal that completed: its CSV is there, not marked partial,
 * and newer than the scene. */
static bool run_complete(const char *exr, const char *csvp, const char *scene)
{
    if (access(exr, R_OK) || older_than(csvp, scene)) return false;
    char *csv = read_whole_file(csvp);
    bool done = csv && !strstr(csv, "\n# PARTIAL");
    free(csv);
    return done;
}

/* The '# key value' header line of a render CSV. */
static double csv_header(const char *text, const char *key)
{
    char pat[128];
    snprintf(pat, sizeof pat, "# %s ", key);
    const char *p = strstr(text, pat);
    return p ? strtod(p + strlen(pat), NULL) : NAN;
}

/* Non-zero fraction of the 'total' rows: all kinds (kind NULL) or one kind. */
static double csv_nonzero(const char *text, const char *kind)
{
    double att = 0, nz = 0;
    for (const char *l = text; l && *l; l = strchr(l, '\n') ? strchr(l, '\n') + 1 : NULL) {
        char m[32], k[32], len[32], tc[32];
        double a, ma, se, af, n;
        if (*l == '#') continue; /* metadata, some of it comma-separated numbers (# nonfinite_by_length) */
        if (sscanf(l, "%31[^,],%31[^,],%31[^,],%31[^,],%lf,%lf,%lf,%lf,%lf", m, k, len, tc, &a, &ma, &se, &af, &n) != 9)
            continue;
        if (strcmp(len, "total") || (kind && strcmp(k, kind))) continue;
        att += a;
        nz += n;
    }
    return att > 0 ? nz / att : NAN;
}

/* mkdir -p */
static void make_dirs(const char *path)
{
    char *p = xstrdup(path);
    for (char *s = p + 1; *s; s++)
        if (*s == '/') {
            *s = 0;
            mkdir(p, 0777);
            *s = '/';
        }
    mkdir(p, 0777);
    free(p);
}

static void fail(const char *msg1, const char *msg2)
{
    fprintf(stderr, "ch6_equal: %s%s\n", msg1, msg2 ? msg2 : "");
    exit(1);
}

static double mean_luminance(const struct image *im)
{
    double m = 0;
    for (int y = 0; y < im->h; y++)
        for (int x = 0; x < im->w; x++)
            m += luminance(img_get(im, x, y));
    return m / ((double)im->w * im->h);
}

/* A run's image against the reference (ref NULL: no reference, every image statistic nan). */
static void image_statistics(struct run *r, const struct image *im, const struct image *ref, double eps, int blk,
                             double *blocks, int cap)
{
    static const enum ch6_q image_q[] = {Q_RELMSE,  Q_RELMSE_SCALED, Q_SPREAD, Q_BLOCK_MEDIAN,
                                         Q_TRIMMED, Q_BLUR4,         Q_BLUR8,  Q_CORRLEN};
    for (size_t k = 0; k < sizeof image_q / sizeof *image_q; k++)
        r->q[image_q[k]] = NAN;
    if (!ref) return;
    r->q[Q_RELMSE] = img_relmse(im, ref, eps);
    r->q[Q_RELMSE_SCALED] = ch6_relmse_scaled(im, ref, eps);
    int n = ch6_block_relmse(im, ref, blk, eps, blocks, cap);
    if (n > cap) n = cap;
    r->q[Q_SPREAD] = ch6_spread(blocks, n);
    r->q[Q_BLOCK_MEDIAN] = ch6_median(blocks, n);
    r->q[Q_TRIMMED] = ch6_trimmed_relmse(im, ref, eps, 0.001);
    r->q[Q_BLUR4] = error_blur_share(im, ref, eps, 4);
    r->q[Q_BLUR8] = error_blur_share(im, ref, eps, 8);
    r->q[Q_CORRLEN] = error_corr_length(im, ref);
}

/* OUT/stats.csv: the statistics that do not depend on the machine's speed (at --spp budgets), one
 * row per method and statistic at the largest budget (runs[method][seed]), for make check-fig6.N
 * (bin/check_stats --key scene,method,statistic --count seeds). A statistic undefined in a run (the
 * correlation length of an error without a correlated part) is left out of its mean, and its row
 * out when fewer than two runs define it. */
static void write_stats(const char *out, const char *name, const struct method *ms, int nm, int seeds,
                        const struct run (*runs)[MAX_SEEDS])
{
    static const struct {
        enum ch6_q q;
        const char *name;
    } st[] = {{Q_RELMSE, "relmse"},
              {Q_RELMSE_SCALED, "relmse_scaled"},
              {Q_BLOCK_MEDIAN, "block_median_relmse"},
              {Q_TRIMMED, "trimmed_relmse"},
              {Q_SPREAD, "block_spread"},
              {Q_BLUR4, "blur4_share"},
              {Q_BLUR8, "blur8_share"},
              {Q_CORRLEN, "corr_length"},
              {Q_NONZERO, "nonzero"},
              {Q_LARGE_NONZERO, "large_nonzero"},
              {Q_NONZERO_CONN, "nonzero_per_connection"},
              {Q_B_RSE, "b_rse"}};
    char *buf = NULL, path[4200], err[1024];
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    csv_meta(f, NULL, "ch6_equal: mean +- standard error over %d seeds at the largest budget", seeds);
    fprintf(f, "scene,method,statistic,mean,se,seeds\n");
    for (int mi = 0; mi < nm; mi++)
        for (size_t k = 0; ms[mi].available && k < sizeof st / sizeof *st; k++) {
            double v[MAX_SEEDS], mean, se;
            int n = 0;
            for (int s = 0; s < seeds; s++)
                if (isfinite(runs[mi][s].q[st[k].q])) v[n++] = runs[mi][s].q[st[k].q];
            if (n < 2) continue;
            mean_se(v, n, &mean, &se);
            fprintf(f, "%s,%s,%s,%.6g,%.3g,%d\n", name, ms[mi].name, st[k].name, mean, se, n);
        }
    fclose(f);
    snprintf(path, sizeof path, "%.4000s/stats.csv", out);
    if (!write_text_atomic(path, buf, err, sizeof err)) fail(err, NULL);
    free(buf);
}

int main(int argc, char **argv)
{
    const char *prog = "ch6_equal", *scene = NULL, *out = NULL, *name = NULL, *refpath = NULL, *res = NULL;
    const char *methods_arg, *extra_arg, *render_arg = NULL, *source, *command, *scale;
    char methods_s[4096], extra_s[1024], render[4096] = "";
    int seeds, refspp, blk, threads, minlen, spp, first_seed;
    double T, t0 = -1;
    bool reuse = false, wall = false;
    double ckpt_every;
    const struct opt opts[] = {
        OPT_SCENE(scene, .help = "scene JSON"),
        {"--name", OPT_STRING, OPT_DST(name), .arg = "NAME",
         .help = "label in the outputs (default: the scene's folder name)"},
        OPT_OUT(out, .arg = "DIR", .help = "output folder"),
        {"--methods", OPT_STRING, OPT_DST(methods_arg), .arg = "LIST", .def = "pssmlt,mmlt,pitp",
         .help = "comma-separated methods; an item NAME=ARGS runs bin/render with ARGS (spaces separate them), e.g. "
                 "'mctls=--method mmlt --large-step mctls'"},
        {"--seeds", OPT_INT, OPT_DST(seeds), .arg = "N", .lo = 2, .hi = MAX_SEEDS,
         .help = "seeds 1..N per method and budget", .def = "4"},
        {"--time", OPT_DOUBLE, OPT_DST(T), .arg = "T", .lo = 0.01, .hi = 1e6,
         .help = "largest budget in seconds per run", .def = "8"},
        {"--spp", OPT_INT, OPT_DST(spp), .arg = "N", .lo = 0, .hi = 1 << 20, .def = "0",
         .help =
             "instead of time budgets, N mutations per pixel per run (bin/render --spp): statistics that do not depend "
             "on the machine's speed, for make check-fig6.N (0: the time budgets)"},
        {"--first-seed", OPT_INT, OPT_DST(first_seed), .arg = "S", .lo = 1, .hi = 1 << 20, .def = "1",
         .help = "seeds S .. S+N-1 (a regression check's seeds differ from its baseline's)"},
        {"--t0", OPT_DOUBLE, OPT_DST(t0), .arg = "S", .lo = 0.01, .hi = 1e6,
         .help = "smallest budget; budgets double from it up to T (default T: one budget)"},
        {"--resolution", OPT_WXH, .str = &res, .arg = "WxH", .lo = 1, .hi = INT_MAX,
         .expect = "WxH with positive integers", .help = "override the camera (also for the reference)"},
        OPT_REFERENCE(refpath, .help = "cached BDPT reference EXR, re-rendered when older than the scene file (default "
                                       "results/reference/NAME-bdpt-WxH-minK-SPP.exr)"),
        {"--reference-spp", OPT_INT, OPT_DST(refspp), .arg = "N", .lo = 0, .hi = 1 << 24, .def = "256",
         .help = "BDPT samples per pixel of the reference (0: no reference, only the render CSVs' counts: the "
                 "non-zero ratios)"},
        OPT_MIN_LENGTH(minlen, .hi = 64, .def = "1",
                       .help =
                           "paths of K segments or more only, reference and runs (1: all; the thesis's chapter 6 uses "
                           "3: no direct lighting)"),
        {"--render-args", OPT_STRING, OPT_DST(extra_arg), .arg = "ARGS",
         .help = "extra bin/render options for every run", .def = "--p-large 0.1"},
        {"--block", OPT_INT, OPT_DST(blk), .arg = "B", .lo = 2, .hi = 1024, .help = "block size of the error spread",
         .def = "16"},
        OPT_THREADS(threads, .hi = 1024, .help = "threads per run", .def = "2"),
        {"--render", OPT_STRING, OPT_DST(render_arg), .arg = "PATH",
         .help = "the renderer (default: bin/render beside this tool)"},
        {"--wall-clock", OPT_FLAG, OPT_DST(wall),
         .help =
             "budgets in wall-clock seconds (bin/render --time); default CPU seconds per thread (--cpu-time), which "
             "other processes on the machine do not shift"},
        {"--source", OPT_STRING, OPT_DST(source), .arg = "TEXT", .def = "thesis ch. 6",
         .help = "the claims' source item, for claims.csv (e.g. 'thesis Figs. 6.4, 6.7')"},
        {"--command", OPT_STRING, OPT_DST(command), .arg = "TEXT", .def = "bin/ch6_equal",
         .help = "the command that reproduces this run, for claims.csv"},
        {"--scale", OPT_STRING, OPT_DST(scale), .arg = "NAME", .def = "custom",
         .help = "the scale's name, for claims.csv"},
        {"--checkpoint", OPT_DOUBLE, OPT_DST(ckpt_every), .arg = "S", .lo = 0, .hi = 1e6, .def = "0",
         .help = "every render (reference too) checkpoints every S seconds, and a rerun after an interruption keeps "
                 "the completed runs and resumes the interrupted one (0: off)"},
        {"--reuse", OPT_FLAG, OPT_DST(reuse),
         .help = "keep the run files already in OUT/runs (same names) instead of rendering"},
        {0}};
    /* Several copies would each run every render; MPI goes through --render instead (README MPI). */
    dist_refuse_ranks();
    opts_parse(
        &(struct opts_spec){.prog = prog, .usage = "usage: ch6_equal --scene FILE --out DIR [options]\n", .opts = opts},
        argc, argv);
    snprintf(methods_s, sizeof methods_s, "%s", methods_arg);
    snprintf(extra_s, sizeof extra_s, "%s", extra_arg);
    if (render_arg) snprintf(render, sizeof render, "%s", render_arg);
    if (!scene || !out) opts_fail(prog, "--scene and --out are required (see --help)");
    if (strlen(out) > 2000) opts_fail(prog, "--out: path too long");
    if (t0 < 0 || spp > 0) t0 = T = spp > 0 ? spp : T;
    if (t0 > T) opts_fail(prog, "--t0 %g is larger than --time %g", t0, T);
    int nb = 0;
    double budgets[MAX_BUDGETS];
    for (double b = t0; b <= T * (1 + 1e-9) && nb < MAX_BUDGETS; b *= 2)
        budgets[nb++] = b;
    if (fabs(budgets[nb - 1] - T) > 1e-9 * T && nb < MAX_BUDGETS) budgets[nb++] = T;
    if (access(scene, R_OK)) opts_fail(prog, "--scene: cannot read '%s'", scene);
    char sname[256];
    if (!name) {
        snprintf(sname, sizeof sname, "%s", scene);
        char *sl = strrchr(sname, '/');
        if (sl) *sl = 0;
        sl = strrchr(sname, '/');
        name = sl ? sl + 1 : sname;
    }
    if (!*render) {
        char self[2048];
        ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
        if (n <= 0) fail("cannot find my own path; give --render", NULL);
        self[n] = 0;
        char *sl = strrchr(self, '/');
        *sl = 0;
        snprintf(render, sizeof render, "%s/render", self);
    }
    if (access(render, X_OK)) opts_fail(prog, "--render: '%s' is not executable", render);
    opts_require_image_output(prog);

    /* Methods: parse and probe. */
    struct method ms[MAX_METHODS];
    int nm = 0;
    char *mdup = xstrdup(methods_s), *save = NULL;
    for (char *item = strtok_r(mdup, ",", &save); item; item = strtok_r(NULL, ",", &save)) {
        if (nm == MAX_METHODS) opts_fail(prog, "--methods: at most %d", MAX_METHODS);
        struct method *m = &ms[nm++];
        memset(m, 0, sizeof *m);
        char *eq = strchr(item, '=');
        if (eq) {
            *eq = 0;
            split_args(eq + 1, m->argv, &m->argc, MAX_ARGS - 24); /* in place: mdup lives to the end */
        } else {
            m->argv[m->argc++] = "--method";
            m->argv[m->argc++] = item;
        }
        snprintf(m->name, sizeof m->name, "%s", item);
        if (!*m->name || m->argc == 0) opts_fail(prog, "--methods: empty item in '%s'", methods_s);
        /* probe: bin/render [method args] --help exits 0 when it accepts them */
        char *pv[MAX_ARGS + 4];
        int pc = 0;
        pv[pc++] = render;
        for (int k = 0; k < m->argc; k++)
            pv[pc++] = m->argv[k];
        pv[pc++] = "--help";
        pv[pc] = NULL;
        m->available = run_cmd(pv, NULL) == 0;
        if (!m->available)
            fprintf(stderr, "ch6_equal: %s: %s does not accept '%s'; skipped\n", m->name, render, eq ? eq + 1 : item);
    }
    char *extra_argv[MAX_ARGS];
    int extra_c = 0;
    char extra_buf[sizeof extra_s];
    memcpy(extra_buf, extra_s, sizeof extra_s);
    split_args(extra_buf, extra_argv, &extra_c, MAX_ARGS - 24);

    make_dirs(out);
    char runsdir[4096], err[1024];
    snprintf(runsdir, sizeof runsdir, "%s/runs", out);
    mkdir(runsdir, 0777);

    /* The reference (cached). */
    char defref[1024], thr[16], spp_s[32], minlen_s[16];
    snprintf(minlen_s, sizeof minlen_s, "%d", minlen);
    snprintf(thr, sizeof thr, "%d", threads);
    struct image *probe_ref = NULL;
    if (!refpath) {
        make_dirs("results/reference");
        snprintf(defref, sizeof defref, "results/reference/%s-bdpt-%s-min%d-%d.exr", name, res ? res : "native", minlen,
                 refspp);
        refpath = defref;
    }
    probe_ref = !refspp || older_than(refpath, scene) ? NULL : img_read(refpath, err, sizeof err);
    if (!probe_ref && refspp) {
        fprintf(stderr, "ch6_equal: rendering the BDPT reference (%d spp) into %s\n", refspp, refpath);
        char prefix[1100];
        snprintf(prefix, sizeof prefix, "%.*s", (int)(strlen(refpath) - 4), refpath);
        snprintf(spp_s, sizeof spp_s, "%d", refspp);
        /* rendered under another name and renamed when complete: an interrupted render writes a
         * partial image, which must never pass for the cached reference */
        char part[1200];
        snprintf(part, sizeof part, "%s.rendering", prefix);
        char *rv[24] = {render,      (char *)scene, "--method", "bdpt",         "--spp",  spp_s,   "--seed", "12345",
                        "--threads", thr,           "--quiet",  "--min-length", minlen_s, "--out", part};
        int c = 15;
        if (res) rv[c++] = "--resolution", rv[c++] = (char *)res;
        if (run_checkpointed(rv, c, part, ckpt_every, NULL) != 0) fail("the reference render failed: ", refpath);
        char exr[1300];
        snprintf(exr, sizeof exr, "%s.exr", part);
        if (rename(exr, refpath) != 0) fail("cannot rename the reference into place: ", refpath);
        snprintf(exr, sizeof exr, "%s.png", part); /* the render's PNG: OUT/reference.png replaces it */
        unlink(exr);
        probe_ref = img_read(refpath, err, sizeof err);
        if (!probe_ref) fail(err, NULL);
    }
    struct image *ref = probe_ref;
    double mlum = ref ? mean_luminance(ref) : NAN, eps = 0.01 * mlum * mlum, expo = 0.5 / mlum;
    char path[4096];
    if (ref && !(mlum > 0)) fail("the reference is black: ", refpath);
    snprintf(path, sizeof path, "%s/reference.png", out);
    if (ref && !img_write_png(ref, expo, path, err, sizeof err)) fail(err, NULL);

    static struct run R[MAX_METHODS][MAX_BUDGETS][MAX_SEEDS];
    int cap = ref ? (ref->w / blk) * (ref->h / blk) + 1 : 1;
    double *blocks = xmalloc(sizeof(double) * (size_t)cap);
    /* Interleaved: seed 1 of every method and budget, then seed 2, ...: a change in the machine's
     * load during the runs then falls on every method alike, not on the one running at the time. */
    for (int s = 1; s <= seeds; s++)
        for (int bi = 0; bi < nb; bi++)
            for (int mi = 0; mi < nm; mi++) {
                struct method *m = &ms[mi];
                if (!m->available) continue;
                char prefix[4096], seed_s[32], time_s[32];
                snprintf(prefix, sizeof prefix, "%.3000s/%.60s-s%d-%s%g", runsdir, m->name, first_seed + s - 1,
                         spp > 0 ? "spp" : "t", budgets[bi]);
                snprintf(seed_s, sizeof seed_s, "%d", first_seed + s - 1);
                snprintf(time_s, sizeof time_s, "%g", budgets[bi]);
                char *rv[MAX_ARGS * 2 + 24];
                int c = 0;
                rv[c++] = render;
                rv[c++] = (char *)scene;
                for (int k = 0; k < m->argc; k++)
                    rv[c++] = m->argv[k];
                for (int k = 0; k < extra_c; k++)
                    rv[c++] = extra_argv[k];
                char *fixed[] = {spp > 0 ? "--spp"
                                 : wall  ? "--time"
                                         : "--cpu-time",
                                 time_s,
                                 "--seed",
                                 seed_s,
                                 "--threads",
                                 thr,
                                 "--min-length",
                                 minlen_s,
                                 "--quiet",
                                 "--out",
                                 prefix};
                for (size_t k = 0; k < sizeof fixed / sizeof *fixed; k++)
                    rv[c++] = fixed[k];
                if (res) {
                    rv[c++] = "--resolution";
                    rv[c++] = (char *)res;
                }
                char log[4200], csvp[4200];
                snprintf(log, sizeof log, "%.4000s.log", prefix);
                snprintf(path, sizeof path, "%.4000s.exr", prefix);
                snprintf(csvp, sizeof csvp, "%.4000s.csv", prefix);
                bool keep = reuse ? !access(path, R_OK) && !access(csvp, R_OK)
                                  : ckpt_every > 0 && run_complete(path, csvp, scene);
                fprintf(stderr, "ch6_equal: %s %s seed %d, %g %s%s\n", name, m->name, first_seed + s - 1, budgets[bi],
                        spp > 0 ? "mutations per pixel" : "s", keep ? " (kept from an earlier run)" : "");
                if (!keep && run_checkpointed(rv, c, prefix, ckpt_every, log) != 0) fail("a render failed; see ", log);
                if (keep && ckpt_every > 0) {
                    /* an interrupt between the render's end and our removal of its checkpoint
                     * leaves one beside complete outputs: stale, so it goes now */
                    char ck[4200];
                    snprintf(ck, sizeof ck, "%.4000s.ckpt", prefix);
                    unlink(ck);
                }
                struct image *im = img_read(path, err, sizeof err);
                if (!im) fail(err, NULL);
                if (ref && (im->w != ref->w || im->h != ref->h)) fail("image and reference sizes differ: ", path);
                struct run *r = &R[mi][bi][s - 1];
                image_statistics(r, im, ref, eps, blk, blocks, cap);
                if (!ref) expo = 0.5 / mean_luminance(im); /* no reference: a PNG is exposed by its own mean */
                if (bi == nb - 1 && s == 1) {
                    snprintf(path, sizeof path, "%.3000s/%.60s.png", out, m->name);
                    if (!img_write_png(im, expo, path, err, sizeof err)) fail(err, NULL);
                    snprintf(path, sizeof path, "%.3000s/%.60s.exr", out, m->name);
                    if (!img_write_exr(im, 1, path, err, sizeof err)) fail(err, NULL);
                }
                img_destroy(im);
                snprintf(path, sizeof path, "%.4000s.csv", prefix);
                char *csv = read_whole_file(path);
                if (!csv) fail("cannot read ", path);
                r->seconds = csv_header(csv, "seconds");
                r->q[Q_MUTATIONS] = csv_header(csv, "mutations");
                r->q[Q_MPS] = csv_header(csv, "mutations_per_second");
                r->q[Q_NONZERO] = csv_nonzero(csv, NULL);
                r->q[Q_LARGE_NONZERO] = csv_nonzero(csv, "large");
                double tried = csv_header(csv, "connections_evaluated");
                r->q[Q_NONZERO_CONN] = tried > 0 ? csv_header(csv, "connections_nonzero") / tried : NAN;
                r->q[Q_B_RSE] = csv_header(csv, "b_rse");
                free(csv);
            }

    /* runs.csv and summary.csv */
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    csv_meta(f, NULL, "ch6_equal: equal-time renders of %s", scene);
    csv_meta_commit(f);
    if (ref)
        csv_meta(f, "reference", "%s (%d spp BDPT)", refpath, refspp);
    else
        csv_meta(f, "reference", "none (--reference-spp 0: the image statistics are nan)");
    csv_meta(f, "render args", "%s", extra_s);
    csv_meta(f, "min_length", "%d", minlen);
    csv_meta(f, "relmse eps", "= 0.01 * (reference mean luminance %.6g)^2", mlum);
    csv_meta(f, NULL,
             "budgets are separate runs with the same seed (no snapshots), methods interleaved seed by seed; %s",
             spp > 0 ? "budget = mutations per pixel (--spp)"
             : wall  ? "wall-clock --time"
                     : "--cpu-time: CPU seconds per thread");
    for (int mi = 0; mi < nm; mi++)
        if (!ms[mi].available) csv_meta(f, "method", "%s not available in this build (skipped)", ms[mi].name);
    fprintf(f, "scene,method,seed,budget,seconds,mutations,mutations_per_s,relmse,block_spread,nonzero,large_nonzero,"
               "block_median_relmse,trimmed_relmse,blur4_share,blur8_share,corr_length,nonzero_per_connection,relmse_"
               "scaled,b_rse\n");
    for (int mi = 0; mi < nm; mi++)
        if (ms[mi].available)
            for (int bi = 0; bi < nb; bi++)
                for (int s = 0; s < seeds; s++) {
                    const double *q = R[mi][bi][s].q;
                    fprintf(
                        f, "%s,%s,%d,%g,%.3f,%.0f,%.0f,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n",
                        name, ms[mi].name, first_seed + s, budgets[bi], R[mi][bi][s].seconds, q[Q_MUTATIONS], q[Q_MPS],
                        q[Q_RELMSE], q[Q_SPREAD], q[Q_NONZERO], q[Q_LARGE_NONZERO], q[Q_BLOCK_MEDIAN], q[Q_TRIMMED],
                        q[Q_BLUR4], q[Q_BLUR8], q[Q_CORRLEN], q[Q_NONZERO_CONN], q[Q_RELMSE_SCALED], q[Q_B_RSE]);
                }
    fclose(f);
    snprintf(path, sizeof path, "%s/runs.csv", out);
    if (!write_text_atomic(path, buf, err, sizeof err)) fail(err, NULL);
    free(buf);

    buf = NULL;
    f = open_memstream(&buf, &len);
    csv_meta(f, NULL, "mean +- standard error over %d seeds", seeds);
    /* the first five quantities in their old columns (scripts read them by position), then the rest */
    static const enum ch6_q col[] = {Q_RELMSE,       Q_SPREAD,        Q_MPS,   Q_NONZERO, Q_LARGE_NONZERO,
                                     Q_BLOCK_MEDIAN, Q_TRIMMED,       Q_BLUR4, Q_BLUR8,   Q_CORRLEN,
                                     Q_NONZERO_CONN, Q_RELMSE_SCALED, Q_B_RSE};
    fprintf(
        f,
        "scene,method,budget,seeds,relmse,relmse_se,block_spread,block_spread_se,mutations_per_s,mutations_per_s_se,"
        "nonzero,nonzero_se,large_nonzero,large_nonzero_se,block_median_relmse,block_median_relmse_se,trimmed_relmse,"
        "trimmed_relmse_se,blur4_share,blur4_share_se,blur8_share,blur8_share_se,corr_length,corr_length_se,"
        "nonzero_per_connection,nonzero_per_connection_se,relmse_scaled,relmse_scaled_se,b_rse,b_rse_se\n");
    double sum[MAX_METHODS][Q_COUNT][2];
    for (int mi = 0; mi < nm; mi++) {
        if (!ms[mi].available) continue;
        for (int bi = 0; bi < nb; bi++) {
            double v[MAX_SEEDS], mean[Q_COUNT], se[Q_COUNT];
            for (int q = 0; q < Q_COUNT; q++) {
                for (int s = 0; s < seeds; s++)
                    v[s] = R[mi][bi][s].q[q];
                mean_se(v, seeds, &mean[q], &se[q]);
            }
            fprintf(f, "%s,%s,%g,%d", name, ms[mi].name, budgets[bi], seeds);
            for (size_t k = 0; k < sizeof col / sizeof *col; k++)
                fprintf(f, ",%.6g,%.3g", mean[col[k]], se[col[k]]);
            fputc('\n', f);
            if (bi == nb - 1)
                for (int q = 0; q < Q_COUNT; q++)
                    sum[mi][q][0] = mean[q], sum[mi][q][1] = se[q];
        }
    }
    fclose(f);
    snprintf(path, sizeof path, "%s/summary.csv", out);
    if (!write_text_atomic(path, buf, err, sizeof err)) fail(err, NULL);
    free(buf);
    struct run last[MAX_METHODS][MAX_SEEDS];
    for (int mi = 0; mi < nm; mi++)
        for (int s = 0; s < seeds; s++)
            last[mi][s] = R[mi][nb - 1][s];
    write_stats(out, name, ms, nm, seeds, (const struct run(*)[MAX_SEEDS])last);

    /* The Markdown table at the largest budget, with the error-vs-time slope. */
    buf = NULL;
    f = open_memstream(&buf, &len);
    fprintf(f,
            "**%s**, %g %s per run (%d threads), %d seeds, paths of length >= %d, reference %d spp BDPT; mean ± "
            "standard error over seeds\n\n",
            name, T,
            spp > 0 ? "mutations per pixel"
            : wall  ? "s (wall clock)"
                    : "s (CPU seconds per thread)",
            threads, seeds, minlen, refspp);
    fprintf(f,
            "| method | relMSE | median block relMSE | block-relMSE spread (CV, %dx%d) | error share after 8x8 blur | "
            "error correlation length (px) | mutations/s | non-zero proposals | large-step non-zero | relMSE slope vs "
            "time | "
            "normalisation's share of relMSE | seed pass rel. s.e. |\n",
            blk, blk);
    fprintf(f, "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (int mi = 0; mi < nm; mi++) {
        if (!ms[mi].available) {
            fprintf(f, "| %s | not available in this build | | | | | | | | | | |\n", ms[mi].name);
            continue;
        }
        double bx[MAX_BUDGETS], by[MAX_BUDGETS];
        for (int bi = 0; bi < nb; bi++) {
            double v[MAX_SEEDS], se;
            for (int s = 0; s < seeds; s++)
                v[s] = R[mi][bi][s].q[Q_RELMSE];
            mean_se(v, seeds, &by[bi], &se);
            bx[bi] = budgets[bi];
        }
        double slope = ch6_loglog_slope(bx, by, nb);
        const double(*q)[2] = sum[mi];
        fprintf(
            f,
            "| %s | %.4g ± %.2g | %.4g ± %.2g | %.3g ± %.2g | %.3g ± %.2g | %.2f ± %.2f | %.0f ± %.0f | %.4f ± %.4f | "
            "%.4f ± %.4f | %.2f | %.0f %% | %.2f %% |\n",
            ms[mi].name, q[Q_RELMSE][0], q[Q_RELMSE][1], q[Q_BLOCK_MEDIAN][0], q[Q_BLOCK_MEDIAN][1], q[Q_SPREAD][0],
            q[Q_SPREAD][1], q[Q_BLUR8][0], q[Q_BLUR8][1], q[Q_CORRLEN][0], q[Q_CORRLEN][1], q[Q_MPS][0], q[Q_MPS][1],
            q[Q_NONZERO][0], q[Q_NONZERO][1], q[Q_LARGE_NONZERO][0], q[Q_LARGE_NONZERO][1], slope,
            100 * (1 - q[Q_RELMSE_SCALED][0] / q[Q_RELMSE][0]) + 0.0, 100 * q[Q_B_RSE][0]);
    }
    fclose(f);
    snprintf(path, sizeof path, "%s/%s.md", out, name);
    if (!write_text_atomic(path, buf, err, sizeof err)) fail(err, NULL);
    fputs(buf, stdout);
    free(buf);

    /* the claims at the largest budget */
    char names[MAX_METHODS][64];
    bool have[MAX_METHODS];
    double cm[MAX_METHODS][Q_COUNT], cs[MAX_METHODS][Q_COUNT];
    for (int mi = 0; mi < nm; mi++) {
        snprintf(names[mi], sizeof names[mi], "%.63s", ms[mi].name); /* method names are short */
        have[mi] = ms[mi].available;
        for (int q = 0; q < Q_COUNT; q++)
            cm[mi][q] = have[mi] ? sum[mi][q][0] : NAN, cs[mi][q] = have[mi] ? sum[mi][q][1] : NAN;
    }
    struct ch6_claims_in ci = {.scene = name,
                               .source = source,
                               .command = command,
                               .scale = scale,
                               .out = out,
                               .budget = T,
                               .unit = spp > 0 ? "mutations per pixel" : "s",
                               .seeds = seeds,
                               .methods = nm,
                               .name = (const char(*)[64])names,
                               .have = have,
                               .mean = (const double(*)[Q_COUNT])cm,
                               .se = (const double(*)[Q_COUNT])cs};
    char *claims = ch6_write_claims(&ci, err, sizeof err);
    if (!claims) fail(err, NULL);
    fputs(claims, stdout);
    free(claims);
    free(blocks);
    free(mdup);
    img_destroy(ref);
    return 0;
}
