/* bin/fig4_6: thesis Figure 4.6. Equal-time renders of the ajar scene with only MMLT large steps,
 * only MCTLS, and the hybrid (MMLT large steps below --hybrid-length, MCTLS from it on), no small
 * steps, over --seeds seeds (interleaved: seed 1 of every method, then seed 2, ...; budgets in CPU
 * seconds per thread); relative MSE against a BDPT reference rendered once and cached, the cost of a
 * proposal (CPU time, and rays from a separate one-thread run of fixed length) and its acceptance.
 * --mutations fixes the proposals per run instead of the time (make check-fig4.6).
 * Writes OUT/fig4.6-runs.csv (one row per run), OUT/fig4.6.csv (mean ± standard error per method),
 * OUT/claims.csv and claims.md (thesis §4.3's claims with their verdicts), OUT/reference.png and
 * OUT/{mmlt-large,mctls,hybrid,mctls-recompute,hybrid-recompute}.{exr,png} of the first seed; the
 * side-by-side PNG and the table come from the Makefile's scripts. mctls-recompute is MCTLS
 * re-evaluating the current state's trials every step: the cost the thesis's ray count assumes
 * (§4.3.1); hybrid-recompute the hybrid with that MCTLS, whose "could perform better than either"
 * (T20) is said at that cost. */
#include "base/parallel.h"
#include "base/util.h"
#include "ch4/ch4_common.h"
#include "common/claims.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/opts.h"
#include "common/table_set.h"
#include "mc/render.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include "scene/accel.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define METHODS 5
#define RAY_RUNS 4 /* one-thread runs (seeds S..S+3) counting rays per proposal */
#define MAX_SEEDS 64
/* mctls-recompute, hybrid-recompute: MCTLS (in the hybrid, from --hybrid-length on) at the cost the
 * thesis's ray count assumes (mlt_opts.mctls_recompute) */
enum { M_MMLT, M_MCTLS, M_HYBRID, M_MCTLS_RECOMPUTE, M_HYBRID_RECOMPUTE };
static const char *const names[METHODS] = {"mmlt-large", "mctls", "hybrid", "mctls-recompute", "hybrid-recompute"};
static const enum large_step kinds[METHODS] = {LARGE_MMLT, LARGE_MCTLS, LARGE_HYBRID, LARGE_MCTLS, LARGE_HYBRID};
static const bool recompute[METHODS] = {false, false, false, true, true};

struct run {
    double seconds, relmse, us_per_proposal, accept;
    long mutations;
};

/* The mean acceptance probability of the run's large-step proposals (MMLT large steps and MCTLS). */
static double acceptance(const struct mlt_stats *st)
{
    const struct accept_cell *l = &st->total[PROPOSAL_LARGE], *m = &st->total[PROPOSAL_MCTLS];
    long n = l->attempts + m->attempts;
    return n ? (l->sum_a + m->sum_a) / (double)n : NAN;
}

/* Rays per proposal: a one-thread run of `n` proposals (the ray counters are the calling thread's,
 * which is the worker of a one-thread run) less one with none (the seed pass and chain starts). */
static double rays_per_proposal(const struct scene *sc, struct mlt_opts o, long n)
{
    o.threads = 1, o.seconds = 0, o.cpu_time = false, o.progress = false;
    struct mlt_result r;
    char err[256];
    double rays[2];
    for (int pass = 0; pass < 2; pass++) {
        o.mutations = pass ? n : 0;
        struct ray_counts a = accel_ray_counts();
        if (!mlt_render(sc, &o, &r, err, sizeof err)) return NAN;
        mlt_result_free(&r);
        struct ray_counts b = accel_ray_counts();
        rays[pass] = (double)(b.closest - a.closest) + (double)(b.shadow - a.shadow);
    }
    return (rays[1] - rays[0]) / (double)n;
}

/* The tool's settings, its scene and reference, and every run's numbers. */
struct fig46 {
    struct opts_figure fo;
    const char *refpath;
    char defref[256], budget[64];
    double seconds;
    long mutations;
    int refspp, hybrid, seeds;
    struct scene *sc;
    struct image *ref;
    struct mlt_opts base;
    struct run R[METHODS][MAX_SEEDS];
    double rays[METHODS], rays_se[METHODS];  /* over RAY_RUNS one-thread runs */
    double mean[METHODS][3], se[METHODS][3]; /* relMSE, CPU time per proposal, acceptance */
};

static void parse(struct fig46 *t, int argc, char **argv)
{
    const struct opt opts[] = {
        OPTS_FIGURE(t->fo, "scenes/ajar/scene.json", "results/fig4.6"),
        {"--seconds", OPT_DOUBLE, OPT_DST(t->seconds), .arg = "S", .lo = 0.01, .hi = 1e6,
         .help = "budget per run, CPU seconds per thread", .def = "4", .paper = "600", .full = "60"},
        OPT_MUTATIONS(t->mutations, .help =
                                        "instead of --seconds, N proposals per run: statistics that do not depend on "
                                        "the machine, for make check-fig4.6"),
        {"--seeds", OPT_INT, OPT_DST(t->seeds), .arg = "N", .lo = 2, .hi = MAX_SEEDS,
         .help = "runs per method (seeds S..S+N-1)", .def = "8"},
        OPT_REFERENCE(t->refpath, .help = "cached BDPT reference EXR (default results/reference/ajar-bdpt-<spp>.exr)"),
        OPT_REFERENCE_SPP(t->refspp, .help = "BDPT samples per pixel of the reference", .def = "256", .paper = "16384",
                          .full = "4096"),
        OPT_HYBRID_LENGTH(t->hybrid, .help = "hybrid: MCTLS from path length K on, MMLT large steps below", .def = "6"),
        {0}};
    opts_parse(&(struct opts_spec){.prog = "fig4_6", .usage = "usage: fig4_6 [options]\n", .opts = opts, .fig = &t->fo},
               argc, argv);
    opts_require_image_input("fig4_6");
    snprintf(t->defref, sizeof t->defref, "results/reference/ajar-bdpt-%d.exr", t->refspp);
    if (!t->refpath) t->refpath = t->defref;
    if (t->mutations)
        snprintf(t->budget, sizeof t->budget, "%ld proposals", t->mutations);
    else
        snprintf(t->budget, sizeof t->budget, "%g CPU s per thread", t->seconds);
}

/* Every method over the seeds, interleaved so that a change in the machine's load falls on every
 * method alike; the first seed's images beside the reference; then the rays per proposal. */
static bool run(struct fig46 *t, char *err, size_t errlen)
{
    const struct opts_figure *fo = &t->fo;
    t->base = (struct mlt_opts){.method = MLT_MMLT,
                                .p_large = 1,
                                .seconds = t->mutations ? 0 : t->seconds,
                                .cpu_time = !t->mutations,
                                .mutations = t->mutations,
                                .seed_paths = fo->paper || fo->full ? 1000000 : 100000,
                                .threads = fo->threads,
                                .max_length = t->sc->max_length,
                                .progress = isatty(2),
                                .hybrid_length = t->hybrid};
    pss_opts_default(&t->base.pss, t->sc->cam.width, t->sc->cam.height);
    for (int s = 0; s < t->seeds; s++)
        for (int m = 0; m < METHODS; m++) {
            struct mlt_opts o = t->base;
            o.large_step = kinds[m];
            o.mctls_recompute = recompute[m];
            o.seed = fo->seed + (uint64_t)s;
            fprintf(stderr, "fig4.6: %s seed %llu, %s\n", names[m], (unsigned long long)o.seed, t->budget);
            struct mlt_result r;
            if (!mlt_render(t->sc, &o, &r, err, errlen) ||
                (s == 0 && !ch4_write_pair(r.img, fo->out, names[m], err, errlen)))
                return false;
            t->R[m][s] =
                (struct run){r.seconds, img_relmse(r.img, t->ref, 0.01),
                             1e6 * r.seconds * fo->threads / (double)r.mutations, acceptance(&r.stats), r.mutations};
            mlt_result_free(&r);
        }
    for (int m = 0; m < METHODS; m++) {
        double v[RAY_RUNS];
        for (int s = 0; s < RAY_RUNS; s++) {
            struct mlt_opts o = t->base;
            o.large_step = kinds[m];
            o.mctls_recompute = recompute[m];
            o.seed = fo->seed + (uint64_t)s;
            o.seed_paths = 20000;
            v[s] = rays_per_proposal(t->sc, o, 20000);
        }
        mean_se(v, RAY_RUNS, &t->rays[m], &t->rays_se[m]);
    }
    return true;
}

/* Per method: relMSE, CPU time per proposal, acceptance (mean, se over seeds). */
static void analyse(struct fig46 *t)
{
    for (int m = 0; m < METHODS; m++)
        for (int q = 0; q < 3; q++) {
            double v[MAX_SEEDS];
            for (int s = 0; s < t->seeds; s++)
                v[s] = q == 0 ? t->R[m][s].relmse : q == 1 ? t->R[m][s].us_per_proposal : t->R[m][s].accept;
            mean_se(v, t->seeds, &t->mean[m][q], &t->se[m][q]);
        }
}

/* A row of OUT/fig4.6-runs.csv (the seed as unsigned: COL_LONG's "%lu") and of OUT/fig4.6.csv. */
struct run_row {
    const char *method;
    long seed;
    struct run run;
};
static const struct column run_cols[] = {COL_STRING(struct run_row, "method", method),
                                         COL_LONG(struct run_row, "seed", "%lu", seed),
                                         COL_DOUBLE(struct run_row, "seconds", "%.3f", run.seconds),
                                         COL_LONG(struct run_row, "mutations", "%ld", run.mutations),
                                         COL_DOUBLE(struct run_row, "relmse", "%.6g", run.relmse),
                                         COL_DOUBLE(struct run_row, "us_per_proposal", "%.6g", run.us_per_proposal),
                                         COL_DOUBLE(struct run_row, "acceptance", "%.6g", run.accept),
                                         {0}};
struct method_row {
    const char *method;
    int seeds;
    double relmse, relmse_se, us, us_se, cost, rays, acc, acc_se, rays_se;
};
static const struct column method_cols[] = {COL_STRING(struct method_row, "method", method),
                                            COL_INT(struct method_row, "seeds", "%d", seeds),
                                            COL_DOUBLE(struct method_row, "relmse", "%.6g", relmse),
                                            COL_DOUBLE(struct method_row, "relmse_se", "%.3g", relmse_se),
                                            COL_DOUBLE(struct method_row, "us_per_proposal", "%.6g", us),
                                            COL_DOUBLE(struct method_row, "us_per_proposal_se", "%.3g", us_se),
                                            COL_DOUBLE(struct method_row, "cost_vs_mmlt", "%.4g", cost),
                                            COL_DOUBLE(struct method_row, "rays_per_proposal", "%.4g", rays),
                                            COL_DOUBLE(struct method_row, "acceptance", "%.6g", acc),
                                            COL_DOUBLE(struct method_row, "acceptance_se", "%.3g", acc_se),
                                            COL_DOUBLE(struct method_row, "rays_per_proposal_se", "%.3g", rays_se),
                                            {0}};

/* OUT/fig4.6-runs.csv: one row per run. */
static bool write_runs(const struct fig46 *t, char *err, size_t errlen)
{
    const struct opts_figure *fo = &t->fo;
    struct table_set tb;
    FILE *f = table_set_open_one(&tb, "fig4.6-runs.csv", run_cols);
    csv_meta_head(
        f, "fig4.6: equal-time MMLT large steps vs MCTLS vs hybrid (p_large = 1, no small steps), one row per run",
        fo->scene, fo->scale);
    csv_meta(f, "threads", "%d", fo->threads);
    csv_meta(f, "budget", "%s", t->budget);
    csv_meta(f, "reference", "%s (%d spp BDPT)", t->refpath, t->refspp);
    csv_meta(f, "hybrid_length", "%d", t->hybrid);
    csv_meta(f, NULL, "relmse = mean over pixels and channels of (I - R)^2 / (R^2 + 0.01)");
    for (int m = 0; m < METHODS; m++)
        for (int s = 0; s < t->seeds; s++)
            table_row(&tb.t[0], &(struct run_row){names[m], (long)(fo->seed + (uint64_t)s), t->R[m][s]});
    return table_set_save(&tb, "fig4_6", fo->out, err, errlen);
}

/* OUT/fig4.6.csv: mean and standard error over the seeds per method. */
static bool write_methods(const struct fig46 *t, char *err, size_t errlen)
{
    const struct opts_figure *fo = &t->fo;
    struct table_set tb;
    FILE *f = table_set_open_one(&tb, "fig4.6.csv", method_cols);
    csv_meta_head(f, "fig4.6: mean and standard error over seeds per method", fo->scene, fo->scale);
    csv_meta(f, "seeds", "%d", t->seeds);
    csv_meta(f, "budget", "%s, %d threads", t->budget, fo->threads);
    csv_meta(f, NULL,
             "rays_per_proposal: one-thread runs of 20000 proposals less ones of none, mean and standard error over %d "
             "seeds",
             RAY_RUNS);
    for (int m = 0; m < METHODS; m++) {
        const double *mean = t->mean[m], *se = t->se[m];
        table_row(&tb.t[0], &(struct method_row){names[m], t->seeds, mean[0], se[0], mean[1], se[1],
                                                 mean[1] / t->mean[0][1], t->rays[m], mean[2], se[2], t->rays_se[m]});
    }
    return table_set_save(&tb, "fig4_6", fo->out, err, errlen);
}

/* "An MCTLS step costs about 5x an MMLT large step" (T18) for MCTLS method m: by CPU time per
 * proposal and, where the thesis's own count is rays, by rays per proposal (over RAY_RUNS runs). */
static void cost_rows(struct claims *cl, const struct fig46 *t, int m, const char *id)
{
    const double(*mean)[3] = t->mean, (*se)[3] = t->se;
    char zs[128], md[256], stat[160];
    double ratio = mean[m][1] / mean[0][1], rse = ratio_se(mean[m][1], se[m][1], mean[0][1], se[0][1]);
    struct verdict v = verdict_similar(ratio, rse, 5, 0, 0.25, t->seeds);
    snprintf(zs, sizeof zs, "5x=%.2f", v.zmin);
    snprintf(md, sizeof md, "5 within ±25 %% (z = %.1f)", v.zmin);
    snprintf(stat, sizeof stat, "CPU time per proposal, %s / MMLT", names[m]);
    claims_row(cl, id, "thesis §4.3.1", "an MCTLS step costs about 5x an MMLT large step", stat, names[m], ratio, rse,
               zs, md, &v);
    if (!recompute[m]) return;
    ratio = t->rays[m] / t->rays[0];
    rse = ratio_se(t->rays[m], t->rays_se[m], t->rays[0], t->rays_se[0]);
    v = verdict_similar(ratio, rse, 5, 0, 0.25, RAY_RUNS);
    snprintf(zs, sizeof zs, "5x=%.2f", v.zmin);
    snprintf(md, sizeof md, "5 within ±25 %% (z = %.1f)", v.zmin);
    snprintf(stat, sizeof stat, "rays per proposal, %s / MMLT (%d runs of 20000 proposals)", names[m], RAY_RUNS);
    claims_row(cl, id, "thesis §4.3.1", "an MCTLS step costs about 5x an MMLT large step (the thesis's ray count)",
               stat, names[m], ratio, rse, zs, md, &v);
}

/* "At equal time both images are similarly noisy" (T19) for MCTLS method m: relMSE within ±25 %. */
static void noise_row(struct claims *cl, const struct fig46 *t, int m, const char *id)
{
    const double(*mean)[3] = t->mean, (*se)[3] = t->se;
    char zs[128], md[256];
    struct verdict v = verdict_similar(mean[m][0], se[m][0], mean[0][0], se[0][0], 0.25, t->seeds);
    snprintf(zs, sizeof zs, "mmlt-large=%.2f", v.zmin);
    snprintf(md, sizeof md, "mmlt-large %.4g ± %.2g, within ±25 %% (z = %.1f)", mean[0][0], se[0][0], v.zmin);
    claims_row(cl, id, "thesis Fig. 4.6, §4.3.1", "at equal time MCTLS and MMLT large steps are similarly noisy",
               "relMSE", names[m], mean[m][0], se[m][0], zs, md, &v);
}

/* "A combination of MMLT large steps for short paths and MCTLS for long paths could perform better
 * than either technique in isolation" (T20, §4.3.1): the hybrid h's relMSE the smallest against MMLT
 * large steps and the MCTLS m it uses from --hybrid-length on, at equal time. */
static void hybrid_row(struct claims *cl, const struct fig46 *t, int h, int m, const char *id)
{
    const double(*mean)[3] = t->mean, (*se)[3] = t->se;
    double rel[METHODS], rel_se[METHODS], z[METHODS];
    bool use[METHODS] = {false};
    use[M_MMLT] = use[m] = use[h] = true;
    for (int k = 0; k < METHODS; k++)
        rel[k] = mean[k][0], rel_se[k] = se[k][0];
    struct verdict v = verdict_extreme(rel, rel_se, use, METHODS, h, -1, t->seeds, z);
    char zs[128], md[256];
    snprintf(zs, sizeof zs, "mmlt-large=%.2f;%s=%.2f", z[M_MMLT], names[m], z[m]);
    snprintf(md, sizeof md, "mmlt-large %.4g ± %.2g (z = %.1f); %s %.4g ± %.2g (z = %.1f)", rel[M_MMLT], rel_se[M_MMLT],
             z[M_MMLT], names[m], rel[m], rel_se[m], z[m]);
    claims_row(cl, id, "thesis §4.3.1", "a hybrid (MMLT large steps short, MCTLS long) performs better than either",
               "relMSE", names[h], rel[h], rel_se[h], zs, md, &v);
}

/* Thesis §4.3: MCTLS is accepted more often, costs about 5x per step, and the two cancel. The cost
 * and the equal-time noise are the thesis's under its cost model (mctls-recompute); the harness's
 * MCTLS keeps the current state's trials, a cheaper method: its rows are the harness's own. */
static char *claims(const struct fig46 *t, char *err, size_t errlen)
{
    const struct opts_figure *fo = &t->fo;
    const double(*mean)[3] = t->mean, (*se)[3] = t->se;
    struct claims cl;
    char command[64], zs[128], md[256];
    snprintf(command, sizeof command, "make fig4.6 SCALE=%s", fo->scale);
    claims_begin(&cl, fo->scale, command, "Claims of thesis §4.3 on %s at %s per run, %d seeds", fo->scene, t->budget,
                 t->seeds);
    const bool two[METHODS] = {true, true, false, false, false};
    double z[METHODS], acc[METHODS], acc_se[METHODS];
    for (int m = 0; m < METHODS; m++)
        acc[m] = mean[m][2], acc_se[m] = se[m][2];
    struct verdict v = verdict_extreme(acc, acc_se, two, METHODS, M_MCTLS, +1, t->seeds, z);
    snprintf(zs, sizeof zs, "mmlt-large=%.2f", z[0]);
    snprintf(md, sizeof md, "mmlt-large %.4g ± %.2g (z = %.1f)", acc[0], acc_se[0], z[0]);
    claims_row(&cl, "harness:T15", "thesis §4.3", "MCTLS is accepted more often than MMLT large steps",
               "mean acceptance probability", "mctls", acc[1], acc_se[1], zs, md, &v);
    cost_rows(&cl, t, M_MCTLS_RECOMPUTE, "T18");
    cost_rows(&cl, t, M_MCTLS, "harness:T18");
    if (!t->mutations) { /* an equal number of proposals says nothing about equal time */
        noise_row(&cl, t, M_MCTLS_RECOMPUTE, "T19");
        noise_row(&cl, t, M_MCTLS, "harness:T19");
        hybrid_row(&cl, t, M_HYBRID_RECOMPUTE, M_MCTLS_RECOMPUTE, "T20");
        hybrid_row(&cl, t, M_HYBRID, M_MCTLS, "harness:T20");
    }
    return claims_finish(&cl, fo->out, err, errlen);
}

int main(int argc, char **argv)
{
    static struct fig46 t;
    parse(&t, argc, argv);
    char err[1024];
    t.sc = opts_figure_scene(&t.fo);
    t.ref = ch4_reference(t.sc, METHOD_BDPT, t.refspp, t.refpath, t.fo.threads, "fig4_6", err, sizeof err);
    bool ok = t.ref && ch4_write_pair(t.ref, t.fo.out, "reference", err, sizeof err) && run(&t, err, sizeof err);
    if (ok) analyse(&t);
    ok = ok && write_runs(&t, err, sizeof err) && write_methods(&t, err, sizeof err);
    ok = ok && ch4_show_claims(claims(&t, err, sizeof err));
    img_destroy(t.ref);
    scene_free(t.sc);
    if (!ok) die(DIE_RUNTIME, "fig4_6", "%s", err);
    return 0;
}
