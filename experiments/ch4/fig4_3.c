/* bin/fig4_3: thesis Figure 4.3. A room seen only by its reflection in a window over darkness
 * (scenes/window): BDPT, PSSMLT and PSSMLT with constrained discrete choices (--cdc: small steps
 * leave the numbers of discrete decisions, here the dielectric's reflect/refract choice, unchanged)
 * at an equal number of samples per pixel (mutations for the MCMC methods), against a BDPT
 * reference rendered once and cached. Over several seeds: relMSE, and the small-step acceptance of
 * each MCMC variant. Writes OUT/fig4.3.csv (method,quantity,seeds,mean,se), OUT/fig4.3-runs.csv
 * (one row per run, with its wall-clock seconds, which the statistics leave out: they do not reproduce),
 * the first seed's images {bdpt,pssmlt,pssmlt-cdc}.{exr,png}, their acceptance statistics
 * {pssmlt,pssmlt-cdc}-stats.csv (the render tool's CSV rows) and reference.{exr,png}; OUT/claims.csv and
 * claims.md: the thesis's statements on the figure (§4.2) with their verdicts over the seeds. */
#include "base/parallel.h"
#include "base/util.h"
#include "camera/camera.h"
#include "ch4/ch4_common.h"
#include "common/claims.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/opts.h"
#include "common/table_set.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define NMETH 3

static const char *prog = "fig4_3";
static const char *const names[NMETH] = {"bdpt", "pssmlt", "pssmlt-cdc"};

/* The tool's settings, scene and reference, and every run's numbers (method m, seed s at
 * m * seeds + s). */
struct fig43 {
    struct opts_figure fo;
    const char *refpath;
    char defref[256];
    int res[2], spp, seeds, refspp;
    double p_large;
    struct scene *sc;
    struct image *ref;
    double *rel, *acc, *sec;
};

static bool write_stats(const struct mlt_stats *st, const char *method, const char *dir, char *err, size_t n)
{
    char path[4096];
    struct text_out t;
    if (text_out_open(&t)) stats_write_csv(t.f, method, st, true);
    snprintf(path, sizeof path, "%s/%s-stats.csv", dir, method);
    return text_out_save(&t, path, err, n);
}

/* Thesis §4.2 on Figure 4.3, at equal samples per pixel. */
static char *claims(const double *rel, const double *acc, int seeds, const char *out, const char *scale, char *err,
                    size_t errlen)
{
    struct claims cl;
    char command[64];
    snprintf(command, sizeof command, "make fig4.3 SCALE=%s", scale);
    claims_begin(&cl, scale, command, "Claims of thesis §4.2 on Fig. 4.3, %d seeds", seeds);
    const bool mcmc[NMETH] = {false, true, true}, all[NMETH] = {true, true, true};
    const char *src = "thesis §4.2, Fig. 4.3";
    ch4_claim_extreme(&cl, "T8", src, "fixing discrete choices raises PSSMLT's small-step acceptance",
                      "small-step acceptance", names, acc, NMETH, mcmc, 2, +1, seeds);
    /* "leading to a low average acceptance ratio" names no level: below one half is the harness's */
    double m, se;
    mean_se(acc + seeds, seeds, &m, &se);
    struct verdict v = verdict_pair(m, se, 0.5, 0, -1, seeds);
    claims_row_against(&cl, "harness:T8", src, "PSSMLT's small-step acceptance on the window is low (below one half)",
                       "small-step acceptance", names[1], m, se, &v, "0.5", "below 0.5");
    ch4_claim_extreme(&cl, "T9", src, "fixing discrete choices lowers PSSMLT's error", "relMSE", names, rel, NMETH,
                      mcmc, 2, -1, seeds);
    ch4_claim_extreme(&cl, "T10", src, "BDPT has difficulty rendering this scene", "relMSE", names, rel, NMETH, all, 0,
                      +1, seeds);
    return claims_finish(&cl, out, err, errlen);
}

static void parse(struct fig43 *t, int argc, char **argv)
{
    t->res[0] = t->res[1] = -1;
    const struct opt opts[] = {
        OPTS_FIGURE(t->fo, "scenes/window/scene.json", "results/fig4.3"),
        OPT_RESOLUTION(t->res, .lo = 1, .hi = 1 << 14, .help = "image size; quick: the scene's", .paper = "256x144"),
        {"--spp", OPT_INT, OPT_DST(t->spp), .arg = "N", .lo = 1, .hi = 1 << 20,
         .help = "samples (mutations) per pixel of every method", .def = "64"},
        OPT_SEEDS(t->seeds, .help = "runs per method, seeds S..S+N-1", .def = "24", .paper = "16"),
        OPT_P_LARGE(t->p_large),
        OPTS_REFERENCE(t->refpath, t->refspp, "BDPT", "results/reference/window-bdpt-WxH-SPP.exr", "1024", "16384"),
        {0}};
    opts_parse(&(struct opts_spec){.prog = prog, .usage = "usage: fig4_3 [options]\n", .opts = opts, .fig = &t->fo},
               argc, argv);
    opts_require_image_input(prog);
}

/* One run of method m; the first seed's image (and MCMC statistics) into OUT. */
static bool run_one(struct fig43 *t, int m, int s, char *err, size_t errlen)
{
    const struct opts_figure *fo = &t->fo;
    const struct scene *sc = t->sc;
    int k = m * t->seeds + s, W = sc->cam.width, H = sc->cam.height;
    struct image *img;
    t->acc[k] = NAN;
    if (m == 0) {
        struct render_opts o = {.method = METHOD_BDPT,
                                .spp = t->spp,
                                .seed = fo->seed + s,
                                .threads = fo->threads,
                                .max_length = sc->max_length,
                                .progress = isatty(2)};
        struct render_stats st;
        img = render_mc(sc, &o, &st);
        t->sec[k] = st.seconds;
    } else {
        struct mlt_opts o = {.method = MLT_PSSMLT,
                             .p_large = t->p_large,
                             .mutations = (long)t->spp * W * H,
                             .seed_paths = fo->paper ? 1000000 : 100000,
                             .seed = fo->seed + s,
                             .threads = fo->threads,
                             .max_length = sc->max_length,
                             .progress = isatty(2)};
        pss_opts_default(&o.pss, W, H);
        o.pss.cdc = m == 2;
        struct mlt_result r;
        if (!mlt_render(sc, &o, &r, err, errlen)) return false;
        t->acc[k] = cell_mean(&r.stats.total[PROPOSAL_SMALL]);
        t->sec[k] = r.seconds + r.seed_seconds;
        bool ok = s != 0 || write_stats(&r.stats, names[m], fo->out, err, errlen);
        img = r.img;
        r.img = NULL;
        mlt_result_free(&r);
        if (!ok) {
            img_destroy(img);
            return false;
        }
    }
    t->rel[k] = img_relmse(img, t->ref, 0.01);
    bool ok = s != 0 || ch4_write_pair(img, fo->out, names[m], err, errlen);
    img_destroy(img);
    return ok;
}

/* A row of OUT/fig4.3-runs.csv (the seed as unsigned: COL_LONG's "%lu"). */
struct run_row {
    const char *method;
    long seed;
    double relmse, small_accept, seconds;
};
static const struct column run_cols[] = {COL_STRING(struct run_row, "method", method),
                                         COL_LONG(struct run_row, "seed", "%lu", seed),
                                         COL_DOUBLE(struct run_row, "relmse", "%.6g", relmse),
                                         COL_DOUBLE(struct run_row, "small_accept", "%.6g", small_accept),
                                         COL_DOUBLE(struct run_row, "seconds", "%.3f", seconds),
                                         {0}};
static const struct column stat_cols[] = {
    COL_STRING(struct ch4_stat_row, "method", config),  COL_STRING(struct ch4_stat_row, "quantity", quantity),
    COL_INT(struct ch4_stat_row, "seeds", "%d", seeds), COL_DOUBLE(struct ch4_stat_row, "mean", "%.6g", mean),
    COL_DOUBLE(struct ch4_stat_row, "se", "%.6g", se),  {0}};

/* The metadata lines of both tables. */
static void write_meta(FILE *f, const void *ctx)
{
    const struct fig43 *t = ctx;
    const struct opts_figure *fo = &t->fo;
    csv_meta_head(f,
                  "fig4.3: BDPT vs PSSMLT vs PSSMLT with constrained discrete choices (--cdc), equal samples per pixel",
                  fo->scene, fo->scale);
    csv_meta(f, "resolution", "%dx%d", t->sc->cam.width, t->sc->cam.height);
    csv_meta(f, "spp", "%d", t->spp);
    csv_meta(f, "p_large", "%g", t->p_large);
    ch4_meta_runs(f, fo->seed, t->seeds, fo->threads);
    csv_meta(f, "reference", "%s (BDPT %d spp)", t->refpath, t->refspp);
    csv_meta(f, NULL,
             "relmse = mean over pixels and channels of (I - R)^2 / (R^2 + 0.01); small_accept = mean "
             "min(1, a) of small steps");
}

/* Method m's rows of OUT/fig4.3.csv (stats). */
static void write_stats_rows(const struct fig43 *t, int m, struct table *stats)
{
    int seeds = t->seeds;
    struct ch4_stat_row row = {.config = names[m], .quantity = "relmse"};
    ch4_stat_row_of(&row, t->rel + m * seeds, seeds);
    table_row(stats, &row);
    if (m > 0) {
        row.quantity = "small_accept";
        ch4_stat_row_of(&row, t->acc + m * seeds, seeds);
        table_row(stats, &row);
    } else {
        /* relMSE(BDPT, R) = V (1/spp + 1/refspp) for BDPT's per-sample variance term V: the
         * reference's own share V / refspp is part of every method's relMSE */
        int spp = t->spp, sum = t->spp + t->refspp;
        row = (struct ch4_stat_row){"reference", "relmse_own", 0, seeds, row.mean * spp / sum, row.se * spp / sum};
        table_row(stats, &row);
    }
}

/* OUT/fig4.3-runs.csv and OUT/fig4.3.csv, with the same metadata. */
static bool write_tables(const struct fig43 *t, char *err, size_t errlen)
{
    struct table_set tb;
    table_set_open(&tb, 2, (const char *[]){"fig4.3-runs.csv", "fig4.3.csv"},
                   (const struct column *[]){run_cols, stat_cols}, write_meta, t);
    for (int m = 0; m < NMETH; m++) {
        for (int s = 0; s < t->seeds; s++) {
            int k = m * t->seeds + s;
            struct run_row row = {names[m], (long)(t->fo.seed + s), t->rel[k], t->acc[k], t->sec[k]};
            table_row(&tb.t[0], &row);
        }
        write_stats_rows(t, m, &tb.t[1]);
    }
    return table_set_save(&tb, prog, t->fo.out, err, errlen);
}

int main(int argc, char **argv)
{
    struct fig43 t = {0};
    parse(&t, argc, argv);
    char err[1024];
    t.sc = opts_figure_scene(&t.fo);
    if (t.res[0] > 0) camera_resize(&t.sc->cam, t.res[0], t.res[1]);
    snprintf(t.defref, sizeof t.defref, "results/reference/window-bdpt-%dx%d-%d.exr", t.sc->cam.width, t.sc->cam.height,
             t.refspp);
    if (!t.refpath) t.refpath = t.defref;
    t.ref = ch4_reference(t.sc, METHOD_BDPT, t.refspp, t.refpath, t.fo.threads, prog, err, sizeof err);
    bool ok = t.ref && ch4_write_pair(t.ref, t.fo.out, "reference", err, sizeof err);
    size_t n = (size_t)NMETH * t.seeds;
    t.rel = xcalloc(n, sizeof *t.rel), t.acc = xcalloc(n, sizeof *t.acc), t.sec = xcalloc(n, sizeof *t.sec);
    for (int m = 0; m < NMETH && ok; m++)
        for (int s = 0; s < t.seeds && ok; s++) {
            fprintf(stderr, "%s: %s, seed %llu (%d of %d)\n", prog, names[m], (unsigned long long)(t.fo.seed + s),
                    s + 1, t.seeds);
            ok = run_one(&t, m, s, err, sizeof err);
        }
    ok = ok && write_tables(&t, err, sizeof err);
    ok = ok && ch4_show_claims(claims(t.rel, t.acc, t.seeds, t.fo.out, t.fo.scale, err, sizeof err));
    free(t.rel), free(t.acc), free(t.sec);
    img_destroy(t.ref);
    scene_free(t.sc);
    if (!ok) die(DIE_RUNTIME, prog, "%s", err);
    return 0;
}
