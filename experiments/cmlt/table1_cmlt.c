/* Table 1 and Figure 3 of the CMLT paper (Pantaleoni, "Charted Metropolis Light Transport", §5):
 * RMSE against a reference of PSS-MLT-1, PSS-MLT-2, PSS-MLT-AVG, PSS-MLT-MIX, CMLT-EPSM and CMLT on
 * the two-light toy (experiments/cmlt/cmlt_scene.h), at two sample budgets, over several seeds.
 * Writes into --out: table1.csv (algorithm,n,rmse: mean over seeds), table1_stats.csv (mean, standard
 * error, seeds, throughput; what `make check-table1-cmlt` compares), table1_seeds.csv, table1.md,
 * reference.exr/.png (cached, keyed by reference.key), <algo>_<n>.exr/.png of the first seed, and
 * claims.csv/claims.md (the paper's orderings per budget with their verdicts, cmlt_claims.h).
 * --bench instead times every algorithm on one core and prints chain steps per second. */
#include "base/util.h"
#include "cmlt/cmlt_claims.h"
#include "cmlt/cmlt_mcmc.h"
#include "cmlt/cmlt_reference.h"
#include "cmlt/cmlt_scene.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/opts.h"
#include "common/outdir.h"
#include "common/table_set.h"
#include "common/text_out.h"
#include "common/verdict.h"
#include "io/image.h"
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define MAX_BUDGETS CMLT_MAX_BUDGETS
#define MAX_SEEDS 1000

struct opts {
    const char *scale, *out, *commit;
    uint64_t budgets[MAX_BUDGETS];
    int nbudgets, seeds, threads, res, ref_spp, swap_every, bench;
    uint64_t seed;
    double p_large, seed_frac;
};

/* --budgets LIST: comma-separated sample counts, suffix k or M, each in [1024, 1e12] */
static bool parse_budgets(const char *s, void *dst, char *why, size_t len)
{
    struct opts *o = dst;
    int n = 0;
    const char *p = s;
    while (*p) {
        char *end;
        errno = 0;
        double v = strtod(p, &end);
        if (errno || end == p) return snprintf(why, len, "cannot read a number in '%s'", s), false;
        if (*end == 'k' || *end == 'K')
            v *= 1e3, end++;
        else if (*end == 'M' || *end == 'm')
            v *= 1e6, end++;
        if (*end && *end != ',') return snprintf(why, len, "unexpected '%c' in '%s'", *end, s), false;
        if (!(v >= 1024 && v <= 1e12))
            return snprintf(why, len, "each budget must be in [1024, 1e12], got '%s'", s), false;
        if (n == MAX_BUDGETS) return snprintf(why, len, "at most %d budgets", MAX_BUDGETS), false;
        o->budgets[n++] = (uint64_t)v;
        p = *end ? end + 1 : end;
    }
    if (!n) return snprintf(why, len, "empty list"), false;
    o->nbudgets = n;
    return true;
}

static void parse(int argc, char **argv, struct opts *o)
{
    struct opts_figure fig = {0}; /* only its scale: the paper defaults */
    *o = (struct opts){0};
    const struct opt opts[] = {
        {"--scale", OPT_CHOICE, OPT_DST(fig.scale_i), .choices = opts_scales, .str = &o->scale,
         .help = "defaults for budgets and seeds", .def = "quick", .env = "SCALE"},
        {"--budgets", OPT_CALL, .dst = o, .call = parse_budgets, .arg = "LIST",
         .help = "comma-separated total samples per algorithm, suffix k or M", .def = "1M,8M", .paper = "16M,128M"},
        {"--seeds", OPT_INT, OPT_DST(o->seeds), .arg = "K", .lo = 1, .hi = MAX_SEEDS,
         .help = "independent runs per algorithm and budget", .def = "10", .paper = "8"},
        OPT_SEED(o->seed, .hi = 1L << 40, .help = "base seed", .def = "1"),
        OPT_THREADS(o->threads, .hi = 256, .help = "worker threads", .def = "2"),
        {"--res", OPT_INT, OPT_DST(o->res), .arg = "N", .lo = 1, .hi = 4096, .help = "image resolution N x N",
         .def = "128"},
        {"--ref-spp", OPT_INT, OPT_DST(o->ref_spp), .arg = "N", .lo = 1, .hi = 1 << 24,
         .help = "reference samples per pixel", .def = "16384", .paper = "65536"},
        OPT_P_LARGE(o->p_large),
        {"--swap-every", OPT_INT, OPT_DST(o->swap_every), .arg = "K", .lo = 1, .hi = 1 << 20,
         .help = "CMLT chart swap every K iterations", .def = "4"},
        {"--seed-frac", OPT_DOUBLE, OPT_DST(o->seed_frac), .arg = "F", .lo = 1e-6, .hi = 1,
         .help = "seed-pass samples per chart = F * n", .def = "0.0625"},
        OPT_OUT(o->out, .arg = "DIR", .help = "output directory", .def = "results/table1-cmlt"),
        {"--commit", OPT_STRING, OPT_DST(o->commit), .arg = "ID", .help = "recorded in the CSV metadata",
         .def = "unknown"},
        {"--bench", OPT_FLAG, OPT_DST(o->bench), .help = "time each algorithm on one thread, print steps/s; no table"},
        {0}};
    opts_parse(
        &(struct opts_spec){
            .prog = "table1_cmlt",
            .usage = "usage: table1_cmlt [options]\n",
            .about = "Reproduces Table 1 and Figure 3 of the CMLT paper on its two-light toy: RMSE of six MCMC\n"
                     "algorithms (PSS-MLT-1/2/AVG/MIX, CMLT-EPSM, CMLT) against a Monte Carlo reference.\n",
            .opts = opts,
            .fig = &fig},
        argc, argv);
}

/* ---- small output helpers ---------------------------------------------------------------- */

/* The error line of a failed write: "table1_cmlt: ..." and exit status 1. */
static void save_or_die(bool ok, const char *err)
{
    if (!ok) die(DIE_RUNTIME, "table1_cmlt", "%s", err);
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static volatile sig_atomic_t g_stop = 0;
static void on_sigint(int sig)
{
    (void)sig;
    g_stop = 1;
}

/* Progress bar on stderr while `progress` climbs to `total`; returns when *finished is set. */
static void progress_bar(const char *what, _Atomic uint64_t *progress, uint64_t total, _Atomic int *finished, double t0)
{
    int tty = isatty(2);
    double last = -1;
    while (!atomic_load(finished)) {
        struct timespec ts = {0, 200 * 1000 * 1000};
        nanosleep(&ts, NULL);
        double t = now() - t0;
        if (!tty && t - last < 10) continue; /* logs: a line every 10 s */
        last = t;
        double f = total ? (double)atomic_load(progress) / total : 1;
        if (f > 1) f = 1;
        int w = 30, k = (int)(f * w);
        fprintf(stderr, "%s%s [%.*s%*s] %5.1f%% %6.1fs%s", tty ? "\r" : "", what, k, "##############################",
                w - k, "", 100 * f, t, tty ? "" : "\n");
    }
    fprintf(stderr, "%s%s done in %.1fs%*s\n", tty ? "\r" : "", what, now() - t0, 30, "");
}

/* ---- reference --------------------------------------------------------------------------- */

struct ref_thread {
    int w, h, spp, threads;
    uint64_t seed;
    double *img;
    struct cmlt_ref_result res;
    _Atomic uint64_t progress;
    _Atomic int finished;
};

static void *ref_thread_main(void *arg)
{
    struct ref_thread *r = arg;
    cmlt_reference(r->w, r->h, r->spp, r->seed, r->threads, r->img, &r->res, &r->progress);
    atomic_store(&r->finished, 1);
    return NULL;
}

/* Loads the cached reference if its key matches, else computes and caches it. */
static struct image *get_reference(const struct opts *o, struct cmlt_ref_result *res)
{
    char path[1024], keypath[1024], key[512], err[512];
    snprintf(path, sizeof path, "%s/reference.exr", o->out);
    snprintf(keypath, sizeof keypath, "%s/reference.key", o->out);
    /* The scene's fingerprint stands for every constant and line of the toy; bump the version when
     * cmlt_reference.c's estimator changes. */
    snprintf(key, sizeof key, "cmlt-reference-v3 res=%d spp=%d scene=%016llx\n", o->res, o->ref_spp,
             (unsigned long long)cmlt_scene_fingerprint());
    FILE *f = fopen(keypath, "r");
    if (f) {
        char line[1024] = "";
        double b0, b1, b2, nr;
        bool ok =
            fgets(line, sizeof line, f) && !strcmp(line, key) && fscanf(f, "%lf %lf %lf %lf", &b0, &b1, &b2, &nr) == 4;
        fclose(f);
        if (ok) {
            struct image *im = img_read(path, err, sizeof err);
            if (im && im->w == o->res && im->h == o->res) {
                *res = (struct cmlt_ref_result){{b0, b1, b2}, nr};
                fprintf(stderr, "reference: cached %s\n", path);
                return im;
            }
            img_destroy(im);
        }
    }
    struct image *im = img_create(o->res, o->res);
    struct ref_thread rt = {
        .w = o->res, .h = o->res, .spp = o->ref_spp, .threads = o->threads, .seed = 0xC3117ull, .img = im->px};
    atomic_init(&rt.progress, 0);
    atomic_init(&rt.finished, 0);
    int sq = (int)sqrt((double)o->ref_spp);
    pthread_t t;
    double t0 = now();
    ASSERT(pthread_create(&t, NULL, ref_thread_main, &rt) == 0);
    progress_bar("reference", &rt.progress, (uint64_t)o->res * o->res * sq * sq, &rt.finished, t0);
    pthread_join(t, NULL);
    *res = rt.res;
    save_or_die(img_write_exr(im, 1.0, path, err, sizeof err), err);
    snprintf(path, sizeof path, "%s/reference.png", o->out);
    save_or_die(img_write_png(im, 1.0, path, err, sizeof err), err);
    struct text_out kt;
    if (text_out_open(&kt))
        fprintf(kt.f, "%s%.17g %.17g %.17g %.17g\n", key, res->b[0], res->b[1], res->b[2], res->noise_rmse);
    save_or_die(text_out_save(&kt, keypath, err, sizeof err), err);
    return im;
}

/* ---- jobs -------------------------------------------------------------------------------- */

struct job {
    int algo, bidx, seed_idx;
    uint64_t n;
    double rmse;
    struct cmlt_stats st;
};

struct pool {
    const struct opts *o;
    const struct image *ref;
    struct job *jobs;
    int njobs;
    _Atomic int next;
    _Atomic uint64_t progress;
    _Atomic int finished;
    _Atomic int running;
    double **keep; /* [bidx * CMLT_NALGO + algo]: image of seed 0 */
};

static double rmse(const double *a, const double *b, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; i++)
        s += (a[i] - b[i]) * (a[i] - b[i]);
    return sqrt(s / n);
}

static void *worker(void *arg)
{
    struct pool *p = arg;
    const struct opts *o = p->o;
    size_t npx = 3 * (size_t)o->res * o->res;
    double *scratch = xmalloc(sizeof(double) * npx);
    for (;;) {
        int k = atomic_fetch_add(&p->next, 1);
        if (k >= p->njobs) break;
        struct job *J = &p->jobs[k];
        struct cmlt_config c;
        cmlt_config_default(&c);
        c.w = c.h = o->res;
        c.n = J->n;
        c.n_seed = (uint64_t)(o->seed_frac * J->n);
        if (c.n_seed < 1024) c.n_seed = 1024;
        c.p_large = o->p_large;
        c.swap_every = o->swap_every;
        double *img = J->seed_idx == 0 ? p->keep[J->bidx * CMLT_NALGO + J->algo] : scratch;
        uint64_t seed = o->seed * 1000003ull + (uint64_t)J->seed_idx;
        uint64_t stream = (uint64_t)J->bidx * 64 + (uint64_t)J->algo;
        cmlt_run((enum cmlt_algo)J->algo, &c, seed, stream, img, &J->st, &p->progress, &g_stop);
        J->rmse = p->ref ? rmse(img, p->ref->px, npx) : 0;
    }
    free(scratch);
    if (atomic_fetch_sub(&p->running, 1) == 1) atomic_store(&p->finished, 1);
    return NULL;
}

static int cmp_job(const void *a, const void *b)
{
    const struct job *x = a, *y = b; /* largest budgets first, then seed, algorithm: load balance */
    if (x->n != y->n) return x->n < y->n ? 1 : -1;
    if (x->seed_idx != y->seed_idx) return x->seed_idx - y->seed_idx;
    return x->algo - y->algo;
}

static void run_pool(struct pool *p, const char *what)
{
    const struct opts *o = p->o;
    uint64_t total = 0;
    for (int i = 0; i < p->njobs; i++)
        total +=
            p->jobs[i].n -
            p->jobs[i].n %
                (p->jobs[i].algo == CMLT_PSS1 || p->jobs[i].algo == CMLT_PSS2 || p->jobs[i].algo == CMLT_EPSM ? 1 : 2);
    atomic_init(&p->next, 0);
    atomic_init(&p->progress, 0);
    atomic_init(&p->finished, 0);
    atomic_init(&p->running, o->threads);
    pthread_t *t = xmalloc(sizeof *t * (size_t)o->threads);
    double t0 = now();
    for (int i = 0; i < o->threads; i++)
        ASSERT(pthread_create(&t[i], NULL, worker, p) == 0);
    progress_bar(what, &p->progress, total, &p->finished, t0);
    for (int i = 0; i < o->threads; i++)
        pthread_join(t[i], NULL);
    free(t);
}

static const char *fmt_n(uint64_t n, char *buf, size_t len)
{
    if (n % 1000000 == 0)
        snprintf(buf, len, "%lluM", (unsigned long long)(n / 1000000));
    else if (n % 1000 == 0)
        snprintf(buf, len, "%lluk", (unsigned long long)(n / 1000));
    else
        snprintf(buf, len, "%llu", (unsigned long long)n);
    return buf;
}

static void bench(const struct opts *o)
{
    uint64_t n = o->budgets[0];
    csv_meta(stdout, NULL, "bench-cmlt: chain steps per second on one core, n = %llu steps, %dx%d image",
             (unsigned long long)n, o->res, o->res);
    printf("algorithm,steps_per_s\n");
    double *img = xmalloc(sizeof(double) * 3 * o->res * o->res);
    for (int a = 0; a < CMLT_NALGO; a++) {
        struct cmlt_config c;
        cmlt_config_default(&c);
        c.w = c.h = o->res;
        c.n = n;
        c.n_seed = 1024;
        c.p_large = o->p_large;
        c.swap_every = o->swap_every;
        struct cmlt_stats st;
        double t0 = now();
        cmlt_run((enum cmlt_algo)a, &c, o->seed, (uint64_t)a, img, &st, NULL, NULL);
        double dt = now() - t0;
        printf("%s,%.4g\n", cmlt_algo_names[a], st.steps / dt);
        fflush(stdout);
    }
    free(img);
}

/* The jobs of every (seed, budget, algorithm), largest budgets first, and room for the first
 * seed's images. */
static void make_pool(struct pool *p)
{
    const struct opts *o = p->o;
    p->njobs = o->seeds * o->nbudgets * CMLT_NALGO;
    p->jobs = xcalloc((size_t)p->njobs, sizeof *p->jobs);
    int k = 0;
    for (int s = 0; s < o->seeds; s++)
        for (int b = 0; b < o->nbudgets; b++)
            for (int a = 0; a < CMLT_NALGO; a++)
                p->jobs[k++] = (struct job){.algo = a, .bidx = b, .seed_idx = s, .n = o->budgets[b]};
    qsort(p->jobs, (size_t)p->njobs, sizeof *p->jobs, cmp_job);
    size_t npx = 3 * (size_t)o->res * o->res;
    p->keep = xmalloc(sizeof(double *) * o->nbudgets * CMLT_NALGO);
    for (int i = 0; i < o->nbudgets * CMLT_NALGO; i++)
        p->keep[i] = xmalloc(sizeof(double) * npx);
}

static void free_pool(struct pool *p)
{
    for (int i = 0; i < p->o->nbudgets * CMLT_NALGO; i++)
        free(p->keep[i]);
    free(p->keep);
    free(p->jobs);
}

/* What the run's tables share: the RMSE mean and standard error per (budget, algorithm), and those
 * of each seed's acceptance and steps per second (the claims'). */
struct summary {
    double mean[MAX_BUDGETS][CMLT_NALGO], se[MAX_BUDGETS][CMLT_NALGO];
    double acc[2][MAX_BUDGETS][CMLT_NALGO], rate[2][MAX_BUDGETS][CMLT_NALGO];
    double wall;
    int partial;
};

/* The run's three CSV tables (table1.csv, table1_stats.csv, table1_seeds.csv): the budget n as
 * unsigned (COL_LONG's "%lu"). */
struct mean_row {
    const char *algorithm;
    long n;
    int seeds;
    double rmse, rmse_se, steps_per_s, acceptance, swap_acceptance;
};
struct seed_row {
    const char *algorithm;
    long n;
    int seed;
    double rmse, b, b1, b2, acceptance, swap_acceptance, seconds;
};
static const struct column mean_cols[] = {COL_STRING(struct mean_row, "algorithm", algorithm),
                                          COL_LONG(struct mean_row, "n", "%lu", n),
                                          COL_DOUBLE(struct mean_row, "rmse", "%.6e", rmse),
                                          {0}};
static const struct column stats_cols[] = {COL_STRING(struct mean_row, "algorithm", algorithm),
                                           COL_LONG(struct mean_row, "n", "%lu", n),
                                           COL_INT(struct mean_row, "seeds", "%d", seeds),
                                           COL_DOUBLE(struct mean_row, "rmse_mean", "%.6e", rmse),
                                           COL_DOUBLE(struct mean_row, "rmse_se", "%.6e", rmse_se),
                                           COL_DOUBLE(struct mean_row, "steps_per_s", "%.4g", steps_per_s),
                                           COL_DOUBLE(struct mean_row, "acceptance", "%.4f", acceptance),
                                           COL_DOUBLE(struct mean_row, "swap_acceptance", "%.4f", swap_acceptance),
                                           {0}};
static const struct column seed_cols[] = {COL_STRING(struct seed_row, "algorithm", algorithm),
                                          COL_LONG(struct seed_row, "n", "%lu", n),
                                          COL_INT(struct seed_row, "seed", "%d", seed),
                                          COL_DOUBLE(struct seed_row, "rmse", "%.6e", rmse),
                                          COL_DOUBLE(struct seed_row, "b", "%.6g", b),
                                          COL_DOUBLE(struct seed_row, "b1", "%.6g", b1),
                                          COL_DOUBLE(struct seed_row, "b2", "%.6g", b2),
                                          COL_DOUBLE(struct seed_row, "acceptance", "%.4f", acceptance),
                                          COL_DOUBLE(struct seed_row, "swap_acceptance", "%.4f", swap_acceptance),
                                          COL_DOUBLE(struct seed_row, "seconds", "%.2f", seconds),
                                          {0}};
enum { T_CSV, T_STATS, T_SEEDS, NTABLES };

/* Every seed's row of one (algorithm, budget), in seed order. */
static void seed_rows(const struct pool *p, int a, int b, struct table *seeds)
{
    for (int s = 0; s < p->o->seeds; s++)
        for (int j = 0; j < p->njobs; j++) {
            const struct job *J = &p->jobs[j];
            if (J->algo != a || J->bidx != b || J->seed_idx != s) continue;
            const struct cmlt_stats *st = &J->st;
            table_row(seeds, &(struct seed_row){cmlt_algo_names[a], (long)J->n, s, J->rmse, st->b[0], st->b[1],
                                                st->b[2], st->steps ? st->acc_sum / st->steps : 0,
                                                st->swaps ? st->swap_acc_sum / st->swaps : 0, st->seconds});
        }
}

/* The rows of one (algorithm, budget): every seed's into T_SEEDS, the mean into T_CSV and T_STATS. */
static void analyse_cell(const struct pool *p, int a, int b, struct summary *sm, struct table *t)
{
    double s1 = 0, s2 = 0, steps = 0, secs = 0, acc = 0, swaps = 0, swacc = 0;
    double va[MAX_SEEDS], vr[MAX_SEEDS];
    int m = 0;
    for (int j = 0; j < p->njobs; j++) {
        const struct job *J = &p->jobs[j];
        if (J->algo != a || J->bidx != b) continue;
        va[m] = J->st.steps ? J->st.acc_sum / J->st.steps : NAN;
        vr[m] = J->st.seconds > 0 ? J->st.steps / J->st.seconds : NAN;
        s1 += J->rmse;
        s2 += J->rmse * J->rmse;
        steps += J->st.steps;
        secs += J->st.seconds;
        acc += J->st.acc_sum;
        swaps += J->st.swaps;
        swacc += J->st.swap_acc_sum;
        m++;
    }
    seed_rows(p, a, b, &t[T_SEEDS]);
    sm->mean[b][a] = s1 / m;
    sm->se[b][a] = m > 1 ? sqrt(fmax(0.0, (s2 - s1 * s1 / m) / (m - 1)) / m) : 0;
    mean_se(va, m, &sm->acc[0][b][a], &sm->acc[1][b][a]);
    mean_se(vr, m, &sm->rate[0][b][a], &sm->rate[1][b][a]);
    struct mean_row row = {cmlt_algo_names[a],
                           (long)p->o->budgets[b],
                           m,
                           sm->mean[b][a],
                           sm->se[b][a],
                           secs > 0 ? steps / secs : 0,
                           steps > 0 ? acc / steps : 0,
                           swaps > 0 ? swacc / swaps : 0};
    table_row(&t[T_CSV], &row);
    table_row(&t[T_STATS], &row);
}

/* table1.md: ours (mean ± standard error over seeds) next to the paper's Table 1. */
static void write_markdown(const struct opts *o, const struct summary *sm, double noise_rmse, FILE *md)
{
    static const double paper[2][CMLT_NALGO] = {{8.287e-2, 4.073e-2, 4.106e-2, 3.663e-2, 3.924e-2, 3.502e-2},
                                                {3.212e-2, 1.488e-2, 1.587e-2, 1.405e-2, 1.467e-2, 1.374e-2}};
    char nb[32];
    fprintf(md,
            "RMSE against the reference (mean ± standard error over %d seeds; same total samples n per "
            "algorithm), next to the paper's Table 1 (their toy, one run).\n\n| algorithm |",
            o->seeds);
    for (int b = 0; b < o->nbudgets; b++)
        fprintf(md, " n = %s |", fmt_n(o->budgets[b], nb, sizeof nb));
    fprintf(md, " paper n = 16M | paper n = 128M |\n| --- |");
    for (int b = 0; b < o->nbudgets; b++)
        fprintf(md, " ---: |");
    fprintf(md, " ---: | ---: |\n");
    for (int a = 0; a < CMLT_NALGO; a++) {
        fprintf(md, "| %s |", cmlt_algo_names[a]);
        for (int b = 0; b < o->nbudgets; b++)
            fprintf(md, " %.3e ± %.1e |", sm->mean[b][a], sm->se[b][a]);
        fprintf(md, " %.3e | %.3e |\n", paper[0][a], paper[1][a]);
    }
    fprintf(md, "\nReference: %d spp stratified MC, own noise RMSE ≈ %.2e. Wall time %.1f s on %d threads.%s\n",
            o->ref_spp, noise_rmse, sm->wall, o->threads, sm->partial ? " **PARTIAL: interrupted.**" : "");
}

/* What the tables' metadata line says: the run's settings (table_set_open's ctx). */
struct run_info {
    const struct opts *o;
    const struct summary *sm;
};

/* The metadata line every table opens with. */
static void write_meta(FILE *f, const void *ctx)
{
    const struct opts *o = ((const struct run_info *)ctx)->o;
    const struct summary *sm = ((const struct run_info *)ctx)->sm;
    csv_meta(f, "table1_cmlt",
             "commit=%s seed=%llu scale=%s seeds=%d threads=%d res=%d ref_spp=%d p_large=%g swap_every=%d seed_frac=%g "
             "seconds=%.1f%s",
             o->commit, (unsigned long long)o->seed, o->scale, o->seeds, o->threads, o->res, o->ref_spp, o->p_large,
             o->swap_every, o->seed_frac, sm->wall, sm->partial ? " PARTIAL (interrupted)" : "");
}

/* table1.csv, table1_stats.csv, table1_seeds.csv and table1.md (md: its text stays in md->buf
 * until text_out_free; a failed write is the error line and exit status 1). */
static void write_tables(const struct pool *p, struct summary *sm, double noise_rmse, struct text_out *md)
{
    const struct opts *o = p->o;
    struct table_set ts;
    table_set_open(&ts, NTABLES, (const char *[]){"table1.csv", "table1_stats.csv", "table1_seeds.csv"},
                   (const struct column *[]){mean_cols, stats_cols, seed_cols}, write_meta, &(struct run_info){o, sm});
    for (int a = 0; a < CMLT_NALGO; a++)
        for (int b = 0; b < o->nbudgets; b++)
            analyse_cell(p, a, b, sm, ts.t);
    if (text_out_open(md)) write_markdown(o, sm, noise_rmse, md->f);
    char path[1024], err[1100];
    save_or_die(table_set_save(&ts, "table1_cmlt", o->out, err, sizeof err), err);
    snprintf(path, sizeof path, "%s/table1.md", o->out);
    save_or_die(text_out_commit(md, path, err, sizeof err), err);
}

/* <algo>_<n>.exr and .png of the first seed. */
static bool write_images(const struct pool *p, char *err, size_t errlen)
{
    const struct opts *o = p->o;
    char path[1024], nb[32];
    for (int b = 0; b < o->nbudgets; b++)
        for (int a = 0; a < CMLT_NALGO; a++) {
            struct image im = {.w = o->res, .h = o->res, .px = p->keep[b * CMLT_NALGO + a]};
            const char *ext[2] = {"exr", "png"};
            for (int e = 0; e < 2; e++) {
                snprintf(path, sizeof path, "%s/%s_%s.%s", o->out, cmlt_algo_names[a],
                         fmt_n(o->budgets[b], nb, sizeof nb), ext[e]);
                bool ok = e ? img_write_png(&im, 1.0, path, err, errlen) : img_write_exr(&im, 1.0, path, err, errlen);
                if (!ok) return false;
            }
        }
    return true;
}

int main(int argc, char **argv)
{
    struct opts o;
    parse(argc, argv, &o);
    if (o.bench) {
        bench(&o);
        return 0;
    }
    signal(SIGINT, on_sigint);
    outdir_require("table1_cmlt", o.out);
    opts_require_image_input("table1_cmlt");
    double t_start = now();
    struct cmlt_ref_result rr;
    struct image *ref = get_reference(&o, &rr);
    fprintf(stderr, "reference: b = %.6g (w1: %.6g, w2: %.6g), own noise RMSE ~ %.3g\n", rr.b[0], rr.b[1], rr.b[2],
            rr.noise_rmse);
    struct pool p = {.o = &o, .ref = ref};
    make_pool(&p);
    run_pool(&p, "chains");
    struct summary sm = {.partial = g_stop != 0, .wall = now() - t_start};
    struct text_out md;
    write_tables(&p, &sm, rr.noise_rmse, &md);

    char command[64], scale[64], err[512];
    snprintf(command, sizeof command, "make table1-cmlt SCALE=%s", o.scale);
    snprintf(scale, sizeof scale, "%s%s", o.scale, sm.partial ? " (interrupted)" : "");
    struct cmlt_claims_in ci = {.dir = o.out,
                                .scale = scale,
                                .command = command,
                                .seeds = o.seeds,
                                .nbudgets = o.nbudgets,
                                .budgets = o.budgets,
                                .mean = sm.mean,
                                .se = sm.se,
                                .acc = sm.acc,
                                .rate = sm.rate};
    char *claims = cmlt_write_claims(&ci, err, sizeof err);
    if (!claims || !write_images(&p, err, sizeof err)) die(DIE_RUNTIME, "table1_cmlt", "%s", err);
    fputs(md.buf, stderr);
    fputs(claims, stderr);
    free(claims);
    text_out_free(&md);
    free_pool(&p);
    img_destroy(ref);
    return sm.partial ? 130 : 0;
}
