/* bin/fig4_2: thesis Figure 4.2. PSSMLT small steps on the diffuse wall (scenes/wall) at square
 * resolutions 1024, 512 and 256, and resolution-aware proposals scaled to the resolution
 * (--rap-resolution: a fixed step size in pixels, that of 1024) at 256; equal mutations per pixel.
 * Over several seeds: the error's correlation lengths in pixels (as in fig4_1: lag where the
 * autocorrelation normalised at lag 1 falls below 1/e), relMSE against a PT reference per
 * resolution, small-step acceptance.
 * Then the glossy-to-glossy case for which the thesis does not scale steps to the resolution
 * (scenes/wall-glossy: camera - glossy wall - glossy panel - light): small-step acceptance at 1024,
 * 512 and 256 without and (512, 256; at 1024 the scaling is 1) with --rap-resolution, at a fixed
 * number of mutations per run (acceptance needs no image statistics), and at 256 the relMSE of
 * both at that number and at a quarter of it (T7: the error against mutations).
 * Writes OUT/fig4.2.csv (config,resolution,quantity,seeds,mean,se; the glossy configurations are
 * glossy-*), OUT/fig4.2-runs.csv, the first seed's images
 * {pssmlt-1024,pssmlt-512,pssmlt-256,rap-resolution-256}.{exr,png}, and OUT/claims.csv and
 * claims.md: the thesis's statements on the figure (§4.1) with their verdicts over the seeds. */
#include "base/parallel.h"
#include "base/util.h"
#include "camera/camera.h"
#include "ch4/ch4_common.h"
#include "ch4/wall_noise.h"
#include "common/claims.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/opts.h"
#include "common/table_set.h"
#include "path/scene_ready.h"
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define NCONF 4
#define NGLOSSY 7

enum { Q_LX, Q_LY, Q_L, Q_RHO1, Q_RELMSE, Q_ACCEPT, NQ };
static const char *qn[NQ] = {"l_x", "l_y", "l", "rho1", "relmse", "small_accept"};
/* The last two are the 256² runs at a quarter of the mutations: T7's error against mutations. */
static const char *gnames[NGLOSSY] = {"glossy-pssmlt-1024",
                                      "glossy-pssmlt-512",
                                      "glossy-pssmlt-256",
                                      "glossy-rap-resolution-512",
                                      "glossy-rap-resolution-256",
                                      "glossy-pssmlt-256-quarter",
                                      "glossy-rap-resolution-256-quarter"};
static const int gres[NGLOSSY] = {1024, 512, 256, 512, 256, 256, 256};
static const bool grap[NGLOSSY] = {false, false, false, true, true, false, true};
static const int gdiv[NGLOSSY] = {1, 1, 1, 1, 1, 4, 4}; /* mutations: --glossy-mutations / gdiv */
static const char *const names[NCONF] = {"pssmlt-1024", "pssmlt-512", "pssmlt-256", "rap-resolution-256"};
static const int res[NCONF] = {1024, 512, 256, 256};
static const char *prog = "fig4_2";

/* The tool's settings and every run's measurements (configuration c, seed s at c * seeds + s). */
struct fig42 {
    struct opts_figure fo;
    const char *glossy_scene;
    long gmut;
    int seeds, refspp, maxlag;
    double mpp, p_large;
    double *q[NQ], *gacc, *grel; /* grel: the glossy runs' relMSE, at 256² only (else nan) */
    double refvar[NCONF], errvar[NCONF];
};

/* Small-step acceptance of one PSSMLT run of `mutations` on the glossy scene at the camera's size,
 * and with a reference its relMSE against it (else *relmse untouched). */
static bool glossy_accept(const struct scene *sc, bool rap_resolution, long mutations, double p_large, uint64_t seed,
                          int threads, const struct image *ref, double *accept, double *relmse, char *err,
                          size_t errlen)
{
    struct mlt_opts o = {.method = MLT_PSSMLT,
                         .p_large = p_large,
                         .mutations = mutations,
                         .seed_paths = 100000,
                         .seed = seed,
                         .threads = threads,
                         .max_length = sc->max_length,
                         .progress = isatty(2)};
    pss_opts_default(&o.pss, sc->cam.width, sc->cam.height);
    o.pss.rap = o.pss.rap_resolution = rap_resolution;
    struct mlt_result r;
    if (!mlt_render(sc, &o, &r, err, errlen)) return false;
    *accept = cell_mean(&r.stats.total[PROPOSAL_SMALL]);
    if (ref) *relmse = img_relmse(r.img, ref, 0.01);
    mlt_result_free(&r);
    return true;
}

/* Thesis §4.1 on Figure 4.2: the diffuse wall's noise at smaller resolutions and with resolution
 * scaling (q: the per-run quantities of the NCONF configurations), and the glossy case's
 * acceptance (gacc: NGLOSSY configurations). */
static char *claims(double *const *q, const double *gacc, const double *grel, int seeds, const char *out,
                    const char *scale, char *err, size_t errlen)
{
    struct claims cl;
    char command[64];
    snprintf(command, sizeof command, "make fig4.2 SCALE=%s", scale);
    claims_begin(&cl, scale, command, "Claims of thesis §4.1 on Fig. 4.2, %d seeds", seeds);
    const bool plain[NCONF] = {true, true, true, false}, at256[NCONF] = {false, false, true, true};
    const char *src = "thesis §4.1, Fig. 4.2";
    const char *blotchy = "smaller images get blotchier noise (PSSMLT, equal mutations per pixel)";
    ch4_claim_extreme(&cl, "T4", src, blotchy, "lag-1 autocorrelation of the error", names, q[Q_RHO1], NCONF, plain, 2,
                      +1, seeds);
    ch4_claim_extreme(&cl, "T4", src, blotchy, "relMSE", names, q[Q_RELMSE], NCONF, plain, 2, +1, seeds);
    ch4_claim_extreme(&cl, "T5", src, "steps scaled to the resolution remove it at 256²",
                      "lag-1 autocorrelation of the error", names, q[Q_RHO1], NCONF, at256, 3, -1, seeds);
    double m[2], se[2];
    mean_se(q[Q_RELMSE] + 3 * seeds, seeds, &m[0], &se[0]);
    mean_se(q[Q_RELMSE], seeds, &m[1], &se[1]);
    struct verdict v = verdict_similar(m[0], se[0], m[1], se[1], 0.05, seeds);
    claims_row_against(&cl, "harness:T5", src, "steps scaled to the resolution give 256² the relMSE of 1024²", "relMSE",
                       names[3], m[0], se[0], &v, "pssmlt-1024-5%", "pssmlt-1024 %.4g ± %.2g within ±5 %%", m[1],
                       se[1]);
    /* glossy: "the average acceptance ratio drops as the resolution decreases" with steps scaled to it,
     * step by step: 512² below 1024² (where the scaling is 1), 256² below 512²; against unscaled
     * steps at 256² it is the harness's comparison */
    const char *drops = "glossy-to-glossy transport: steps scaled to the resolution lose acceptance as it decreases";
    const bool g512[NGLOSSY] = {true, false, false, true, false}, g256[NGLOSSY] = {false, false, false, true, true},
               gplain[NGLOSSY] = {false, false, true, false, true};
    ch4_claim_extreme(&cl, "T6", src, drops, "small-step acceptance, 512² against 1024² (scenes/wall-glossy)", gnames,
                      gacc, NGLOSSY, g512, 3, -1, seeds);
    ch4_claim_extreme(&cl, "T6", src, drops, "small-step acceptance, 256² against 512² (scenes/wall-glossy)", gnames,
                      gacc, NGLOSSY, g256, 4, -1, seeds);
    ch4_claim_extreme(&cl, "harness:T6", src, "at 256² steps scaled to the resolution have the lower acceptance",
                      "small-step acceptance against unscaled steps at 256² (scenes/wall-glossy)", gnames, gacc,
                      NGLOSSY, gplain, 4, -1, seeds);
    /* T7: "leading to slower convergence rates": at 256² the scaled steps' error is the larger along
     * the error-against-mutations curve, at a quarter of the mutations and at all of them */
    const char *slower = "in glossy-to-glossy transport that loss of acceptance slows convergence";
    const bool gquarter[NGLOSSY] = {[5] = true, [6] = true};
    ch4_claim_extreme(&cl, "T7", src, slower, "relMSE at 256², a quarter of the mutations (scenes/wall-glossy)", gnames,
                      grel, NGLOSSY, gquarter, 6, +1, seeds);
    ch4_claim_extreme(&cl, "T7", src, slower, "relMSE at 256², all the mutations (scenes/wall-glossy)", gnames, grel,
                      NGLOSSY, gplain, 4, +1, seeds);
    /* the rate read literally, the harness's: the slope of log relMSE against log mutations per seed
     * (a seed's two runs share it), the scaled steps' the shallower */
    double *sl = xcalloc((size_t)seeds, sizeof *sl), sm[2], se2[2];
    for (int k = 0; k < 2; k++) {
        for (int s = 0; s < seeds; s++)
            sl[s] = log(grel[(k ? 4 : 2) * seeds + s] / grel[(k ? 6 : 5) * seeds + s]) / log(4.0);
        mean_se(sl, seeds, &sm[k], &se2[k]);
    }
    free(sl);
    v = verdict_pair(sm[1], se2[1], sm[0], se2[0], +1, seeds);
    claims_row_against(&cl, "harness:T7", src,
                       "scaled steps' error falls more slowly with the mutations (the rate as a slope)",
                       "slope of log relMSE against log mutations at 256², a quarter to all (scenes/wall-glossy)",
                       gnames[4], sm[1], se2[1], &v, gnames[2], "%s %.3g ± %.2g", gnames[2], sm[0], se2[0]);
    return claims_finish(&cl, out, err, errlen);
}

static void parse(struct fig42 *t, int argc, char **argv)
{
    const struct opt opts[] = {
        OPTS_FIGURE(t->fo, "scenes/wall/scene.json", "results/fig4.2"),
        OPT_MPP(t->mpp, .lo = 0.01, .hi = 1e6, .help = "PSSMLT mutations per pixel", .def = "4", .paper = "64"),
        OPT_SEEDS(t->seeds, .help = "runs per configuration, seeds S..S+N-1", .def = "4", .paper = "8"),
        OPT_P_LARGE(t->p_large),
        {"--max-lag", OPT_INT, OPT_DST(t->maxlag), .arg = "L", .lo = 2, .hi = 255,
         .help = "autocorrelation lags 0..L pixels", .def = "64"},
        {"--glossy-scene", OPT_STRING, OPT_DST(t->glossy_scene), .arg = "FILE",
         .help = "the glossy-to-glossy scene of the acceptance runs", .def = "scenes/wall-glossy/scene.json"},
        {"--glossy-mutations", OPT_INT, OPT_DST(t->gmut), .arg = "N", .lo = 1000, .hi = 1L << 40,
         .help = "PSSMLT mutations per glossy run, at every resolution", .def = "262144", .paper = "4194304"},
        OPT_REFERENCE_SPP(t->refspp,
                          .help = "PT samples per pixel of the references, cached as "
                                  "results/reference/wall-pt-NxN-SPP.exr",
                          .def = "32", .paper = "1024"),
        {0}};
    opts_parse(&(struct opts_spec){.prog = prog, .usage = "usage: fig4_2 [options]\n", .opts = opts, .fig = &t->fo},
               argc, argv);
    opts_require_image_input(prog);
}

/* The diffuse wall's configurations over the seeds, each against the PT reference of its
 * resolution; the first seed's render of each. */
static bool run_wall(struct fig42 *t, struct scene *sc, char *err, size_t errlen)
{
    const struct opts_figure *fo = &t->fo;
    int seeds = t->seeds;
    struct wall_cfg cfg = {.p_large = t->p_large,
                           .mpp = t->mpp,
                           .seed_paths = fo->paper ? 1000000 : 100000,
                           .threads = fo->threads,
                           .maxlag = t->maxlag};
    for (int i = 0; i < NQ; i++)
        t->q[i] = xcalloc((size_t)NCONF * seeds, sizeof(double));
    struct image *ref = NULL;
    bool ok = true;
    for (int c = 0; c < NCONF && ok; c++) {
        camera_resize(&sc->cam, res[c], res[c]);
        if (!ref || ref->w != res[c]) {
            char refpath[256];
            snprintf(refpath, sizeof refpath, "results/reference/wall-pt-%dx%d-%d.exr", res[c], res[c], t->refspp);
            img_destroy(ref);
            ref = ch4_reference(sc, METHOD_PT, t->refspp, refpath, fo->threads, prog, err, errlen);
            if (!ref) return false;
        }
        t->refvar[c] = ch4_pixel_noise_var(ref);
        cfg.rap = cfg.rap_resolution = c == 3;
        for (int s = 0; s < seeds && ok; s++) {
            fprintf(stderr, "%s: %s, seed %llu (%d of %d)\n", prog, names[c], (unsigned long long)(fo->seed + s), s + 1,
                    seeds);
            struct wall_meas m;
            struct image *img = wall_run(sc, &cfg, fo->seed + s, ref, &m, err, errlen);
            if (!img) {
                ok = false;
                break;
            }
            int k = c * seeds + s;
            double *const *q = t->q;
            q[Q_LX][k] = m.lx, q[Q_LY][k] = m.ly, q[Q_L][k] = 0.5 * (m.lx + m.ly);
            q[Q_RHO1][k] = 0.5 * (m.rho1_x + m.rho1_y), q[Q_RELMSE][k] = m.relmse, q[Q_ACCEPT][k] = m.accept;
            t->errvar[c] += m.err_var / seeds;
            ok = s != 0 || ch4_write_pair(img, fo->out, names[c], err, errlen);
            wall_meas_free(&m);
            img_destroy(img);
        }
    }
    img_destroy(ref);
    return ok;
}

/* The glossy-to-glossy scene's acceptance runs. A load error is one line and exit status 2. */
static bool run_glossy(struct fig42 *t, char *err, size_t errlen)
{
    struct scene *gsc = scene_load(t->glossy_scene, err, errlen);
    if (!gsc) die(DIE_USAGE, prog, "%s", err);
    t->gacc = xcalloc((size_t)NGLOSSY * t->seeds, sizeof *t->gacc);
    t->grel = xcalloc((size_t)NGLOSSY * t->seeds, sizeof *t->grel);
    struct image *ref = NULL;
    bool ok = true;
    for (int c = 0; c < NGLOSSY && ok; c++) {
        camera_resize(&gsc->cam, gres[c], gres[c]);
        if (gres[c] == 256 && !ref) { /* T7: the error at 256², scaled against unscaled steps */
            char refpath[256];
            snprintf(refpath, sizeof refpath, "results/reference/wall-glossy-bdpt-256x256-%d.exr", t->refspp);
            ok = (ref = ch4_reference(gsc, METHOD_BDPT, t->refspp, refpath, t->fo.threads, prog, err, errlen));
        }
        for (int s = 0; s < t->seeds && ok; s++) {
            fprintf(stderr, "%s: %s, seed %llu (%d of %d)\n", prog, gnames[c], (unsigned long long)(t->fo.seed + s),
                    s + 1, t->seeds);
            t->grel[c * t->seeds + s] = NAN;
            ok = glossy_accept(gsc, grap[c], t->gmut / gdiv[c], t->p_large, t->fo.seed + s, t->fo.threads,
                               gres[c] == 256 ? ref : NULL, &t->gacc[c * t->seeds + s], &t->grel[c * t->seeds + s], err,
                               errlen);
        }
    }
    img_destroy(ref);
    scene_free(gsc);
    return ok;
}

/* A row of OUT/fig4.2-runs.csv: the quantities as text, since a glossy run has small_accept only
 * (the other cells empty); the seed as unsigned (COL_LONG's "%lu"). */
struct run_row {
    const char *config;
    int resolution;
    long seed;
    const char *q[NQ];
};
static const struct column stat_cols[] = {COL_STRING(struct ch4_stat_row, "config", config),
                                          COL_INT(struct ch4_stat_row, "resolution", "%d", resolution),
                                          COL_STRING(struct ch4_stat_row, "quantity", quantity),
                                          COL_INT(struct ch4_stat_row, "seeds", "%d", seeds),
                                          COL_DOUBLE(struct ch4_stat_row, "mean", "%.6g", mean),
                                          COL_DOUBLE(struct ch4_stat_row, "se", "%.6g", se),
                                          {0}};

/* The metadata lines of both tables. */
static void write_meta(FILE *f, const void *ctx)
{
    const struct fig42 *t = ctx;
    const struct opts_figure *fo = &t->fo;
    csv_meta_head(f,
                  "fig4.2: PSSMLT small steps on a square diffuse wall at 1024, 512, 256 and with"
                  " --rap-resolution (reference 1024 px) at 256",
                  fo->scene, fo->scale);
    csv_meta(f, "mutations_per_pixel", "%g", t->mpp);
    csv_meta(f, "p_large", "%g", t->p_large);
    csv_meta(f, "kernel", "kelemen s1 1/1024 s2 1/64");
    ch4_meta_runs(f, fo->seed, t->seeds, fo->threads);
    csv_meta(f, "reference", "PT %d spp", t->refspp);
    for (int c = 0; c < NCONF; c++)
        csv_meta(f, NULL, "%s: reference pixel-noise variance %.4g, error variance %.4g", names[c], t->refvar[c],
                 t->errvar[c]);
    csv_meta(f, NULL,
             "l_x, l_y = lag (pixels) where the error's autocorrelation normalised at lag 1 falls below 1/e;"
             " l = their mean; rho1 = mean lag-1 autocorrelation");
    csv_meta(
        f, "glossy",
        "%s, %ld mutations per run, *-quarter a quarter of them (glossy-*: small_accept; at 256 also relmse against "
        "a %d-spp BDPT reference)",
        t->glossy_scene, t->gmut, t->refspp);
}

/* One run's row: quantity i from x[i] (NULL: an empty cell). */
static void run_row(struct table *runs, const char *config, int resolution, uint64_t seed, const double *const *x)
{
    char cell[NQ][32];
    struct run_row row = {.config = config, .resolution = resolution, .seed = (long)seed};
    for (int i = 0; i < NQ; i++) {
        cell[i][0] = 0;
        if (x[i]) snprintf(cell[i], sizeof cell[i], "%.6g", *x[i]);
        row.q[i] = cell[i];
    }
    table_row(runs, &row);
}

/* The rows of OUT/fig4.2-runs.csv (runs) and OUT/fig4.2.csv (stats). */
static void write_rows(const struct fig42 *t, struct table *runs, struct table *stats)
{
    int seeds = t->seeds;
    for (int c = 0; c < NCONF; c++) {
        for (int s = 0; s < seeds; s++) {
            const double *x[NQ];
            for (int i = 0; i < NQ; i++)
                x[i] = &t->q[i][c * seeds + s];
            run_row(runs, names[c], res[c], t->fo.seed + s, x);
        }
        for (int i = 0; i < NQ; i++) {
            struct ch4_stat_row row = {.config = names[c], .quantity = qn[i], .resolution = res[c]};
            ch4_stat_row_of(&row, t->q[i] + c * seeds, seeds);
            table_row(stats, &row);
        }
    }
    for (int c = 0; c < NGLOSSY; c++) {
        bool rel = gres[c] == 256;
        for (int s = 0; s < seeds; s++)
            run_row(runs, gnames[c], gres[c], t->fo.seed + s,
                    (const double *[NQ]){
                        [Q_ACCEPT] = &t->gacc[c * seeds + s], [Q_RELMSE] = rel ? &t->grel[c * seeds + s] : NULL});
        struct ch4_stat_row row = {.config = gnames[c], .quantity = "small_accept", .resolution = gres[c]};
        ch4_stat_row_of(&row, t->gacc + c * seeds, seeds);
        table_row(stats, &row);
        if (!rel) continue;
        row = (struct ch4_stat_row){.config = gnames[c], .quantity = "relmse", .resolution = gres[c]};
        ch4_stat_row_of(&row, t->grel + c * seeds, seeds);
        table_row(stats, &row);
    }
}

/* OUT/fig4.2-runs.csv and OUT/fig4.2.csv, with the same metadata. */
static bool write_tables(const struct fig42 *t, char *err, size_t errlen)
{
    struct column run_cols[NQ + 4] = {COL_STRING(struct run_row, "config", config),
                                      COL_INT(struct run_row, "resolution", "%d", resolution),
                                      COL_LONG(struct run_row, "seed", "%lu", seed)};
    table_columns(run_cols + 3, NQ, qn, COL_STR, offsetof(struct run_row, q), sizeof(const char *), "%s");
    run_cols[NQ + 3] = (struct column){0};
    struct table_set tb;
    table_set_open(&tb, 2, (const char *[]){"fig4.2-runs.csv", "fig4.2.csv"},
                   (const struct column *[]){run_cols, stat_cols}, write_meta, t);
    write_rows(t, &tb.t[0], &tb.t[1]);
    return table_set_save(&tb, prog, t->fo.out, err, errlen);
}

int main(int argc, char **argv)
{
    struct fig42 t = {0};
    parse(&t, argc, argv);
    char err[1024];
    struct scene *sc = opts_figure_scene(&t.fo);
    bool ok = run_wall(&t, sc, err, sizeof err);
    scene_free(sc);
    ok = ok && run_glossy(&t, err, sizeof err) && write_tables(&t, err, sizeof err);
    ok = ok && ch4_show_claims(claims(t.q, t.gacc, t.grel, t.seeds, t.fo.out, t.fo.scale, err, sizeof err));
    free(t.gacc);
    free(t.grel);
    for (int i = 0; i < NQ; i++)
        free(t.q[i]);
    if (!ok) die(DIE_RUNTIME, prog, "%s", err);
    return 0;
}
