/* Table 1 and Figure 3 of the CMLT paper (Pantaleoni, "Charted Metropolis Light Transport", §5):
 * RMSE against a reference of PSS-MLT-1, PSS-MLT-2, PSS-MLT-AVG, PSS-MLT-MIX, CMLT-EPSM and CMLT on
 * the two-light toy (experiments/cmlt/cmlt_scene.h), at two sample budgets, over several seeds.
 * Writes into --out: table1.csv (algorithm,n,rmse: mean over seeds), table1_stats.csv (mean, standard
 * error, seeds, throughput; what `make check-table1-cmlt` compares), table1_seeds.csv, table1.md,
 * reference.exr/.png (cached, keyed by reference.key), <algo>_<n>.exr/.png of the first seed, and
 * claims.csv/claims.md (the paper's orderings per budget with their verdicts, cmlt_claims.h).
 * --bench instead times every algorithm on one core and prints chain steps per second. Here: the
 * options, the interruption flag and the order of the steps; the runs are table1_runs.c's, the
 * tables table1_write.c's. */
#include "base/parallel.h"
#include "base/util.h"
#include "cmlt/table1.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/opts.h"
#include "common/outdir.h"
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>

/* --budgets LIST: comma-separated sample counts, suffix k or M, each in [1024, 1e12] */
static bool parse_budgets(const char *s, void *dst, char *why, size_t len)
{
    struct table1_opts *o = dst;
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
        if (n == TABLE1_MAX_BUDGETS) return snprintf(why, len, "at most %d budgets", TABLE1_MAX_BUDGETS), false;
        o->budgets[n++] = (uint64_t)v;
        p = *end ? end + 1 : end;
    }
    if (!n) return snprintf(why, len, "empty list"), false;
    o->nbudgets = n;
    return true;
}

static void parse(int argc, char **argv, struct table1_opts *o)
{
    struct opts_figure fig = {0}; /* only its scale: the paper defaults */
    *o = (struct table1_opts){0};
    const struct opt opts[] = {
        {"--scale", OPT_CHOICE, OPT_DST(fig.scale_i), .choices = opts_scales, .str = &o->scale,
         .help = "defaults for budgets and seeds (full is the paper's: the toy affords it)", .def = "quick",
         .env = "SCALE"},
        {"--budgets", OPT_CALL, .dst = o, .call = parse_budgets, .arg = "LIST",
         .help = "comma-separated total samples per algorithm, suffix k or M", .def = "1M,8M", .paper = "16M,128M",
         .full = "16M,128M"},
        {"--seeds", OPT_INT, OPT_DST(o->seeds), .arg = "K", .lo = 1, .hi = TABLE1_MAX_SEEDS,
         .help = "independent runs per algorithm and budget", .def = "10", .paper = "8", .full = "8"},
        OPT_SEED(o->seed, .hi = 1L << 40, .help = "base seed", .def = "1"),
        OPT_THREADS(o->threads, .hi = 256, .help = "worker threads", .def = "2"),
        {"--res", OPT_INT, OPT_DST(o->res), .arg = "N", .lo = 1, .hi = 4096, .help = "image resolution N x N",
         .def = "128"},
        {"--ref-spp", OPT_INT, OPT_DST(o->ref_spp), .arg = "N", .lo = 1, .hi = 1 << 24,
         .help = "reference samples per pixel", .def = "16384", .paper = "65536", .full = "65536"},
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

static volatile sig_atomic_t g_stop = 0;
static void on_sigint(int sig)
{
    (void)sig;
    g_stop = 1;
}

/* --bench: chain steps per second of every algorithm on one thread (make bench-cmlt). */
static void bench(const struct table1_opts *o)
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
        double t0 = now_seconds();
        cmlt_run((enum cmlt_algo)a, &c, o->seed, (uint64_t)a, img, &st, NULL, NULL);
        double dt = now_seconds() - t0;
        printf("%s,%.4g\n", cmlt_algo_names[a], st.steps / dt);
        fflush(stdout);
    }
    free(img);
}

int main(int argc, char **argv)
{
    struct table1_opts o;
    parse(argc, argv, &o);
    if (o.bench) {
        bench(&o);
        return 0;
    }
    signal(SIGINT, on_sigint);
    outdir_require("table1_cmlt", o.out);
    opts_require_image_input("table1_cmlt");
    double t_start = now_seconds();
    struct cmlt_ref_result rr;
    struct image *ref = table1_reference(&o, &rr);
    fprintf(stderr, "reference: b = %.6g (w1: %.6g, w2: %.6g), own noise RMSE ~ %.3g\n", rr.b[0], rr.b[1], rr.b[2],
            rr.noise_rmse);
    struct table1_pool p = {.o = &o, .ref = ref, .stop = &g_stop};
    table1_pool_make(&p);
    table1_pool_run(&p, "chains");
    struct table1_summary sm = {.partial = g_stop != 0, .wall = now_seconds() - t_start};
    struct text_out md;
    table1_write_tables(&p, &sm, rr.noise_rmse, &md);

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
    if (!claims || !table1_write_images(&p, err, sizeof err)) die(DIE_RUNTIME, "table1_cmlt", "%s", err);
    fputs(md.buf, stderr);
    fputs(claims, stderr);
    free(claims);
    text_out_free(&md);
    table1_pool_free(&p);
    img_destroy(ref);
    return sm.partial ? 130 : 0;
}
