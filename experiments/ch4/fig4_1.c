/* bin/fig4_1: thesis Figure 4.1. PSSMLT small steps on a diffuse wall (scenes/wall) at 16:9, the
 * isotropic kernel against resolution-aware proposals (--rap: image steps scaled by the aspect
 * ratio), equal mutations. Measures the shape of the noise: the normalised autocorrelation of the
 * error image (render - PT reference, luminance, render scaled to the reference's mean) along x and
 * y, the correlation lengths where it falls below 1/e, and their ratio, over several seeds.
 * Writes OUT/fig4.1.csv (variant,quantity,seeds,mean,se), OUT/fig4.1-runs.csv (one row per run),
 * OUT/fig4.1-profiles.csv (variant,lag,rho_x,rho_x_se,rho_y,rho_y_se), and the first seed's
 * images {iso,rap}.{exr,png}, error-{iso,rap}.png and reference.{exr,png}; OUT/claims.csv and claims.md:
 * the thesis's statements on the figure (§4.1) with their verdicts over the seeds, and the isotropic
 * small step's mean displacement in pixels, x over y (T2). */
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
#include "sampler/pss.h"
#include "stats/noise_corr.h"
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NVAR 2

static const char *prog = "fig4_1";
static const char *const names[NVAR] = {"iso", "rap"};
/* per run: the quantities of the summary (then the error variance, apart) */
enum { Q_LX, Q_LY, Q_RATIO, Q_RHO1X, Q_RHO1Y, Q_RELMSE, Q_ACCEPT, NQ };
static const char *const qn[NQ] = {"l_x", "l_y", "ratio", "rho1_x", "rho1_y", "relmse", "small_accept"};

/* The tool's settings, scene and reference, and every run's measurements (run k = v * seeds + s). */
struct fig41 {
    struct opts_figure fo;
    const char *refpath;
    char defref[256];
    int res[2], seeds, refspp, maxlag;
    double mpp, p_large;
    struct scene *sc;
    struct image *ref;
    double ref_var;
    double *q[NQ], *evar, *rx, *ry; /* rx, ry: maxlag + 1 lags per run */
};

enum { STEPS = 1000000 }; /* small steps drawn for T2's displacement ratio */

/* Thesis §4.1 (T2): "the isotropic mutation will move approximately twice as far on the horizontal
 * axis" on a 16:9 image. A small step's mean displacement in pixels along x over that along y,
 * through the chains' own kernel (sampler/pss.h pss_small_step) on the image dimensions: STEPS steps
 * from uniform points, each the wrapped distance times the image's width or height; the ratio's
 * first-order standard error from the two means'. */
static void step_ratio(int w, int h, uint64_t seed, double *r, double *se)
{
    struct pss_opts o;
    pss_opts_default(&o, w, h);
    struct pss_sampler *p = xmalloc(sizeof *p);
    pss_init(p, &o, seed, 0);
    rng u;
    rng_seed(&u, seed, 1);
    double s[2] = {0, 0}, q[2] = {0, 0};
    for (int i = 0; i < STEPS; i++)
        for (int a = 0; a < 2; a++) {
            double u0 = rng_uniform(&u), d = fabs(pss_small_step(p, a ? DIM_IMAGE_Y : DIM_IMAGE_X, u0) - u0);
            d = fmin(d, 1 - d) * (a ? h : w);
            s[a] += d, q[a] += d * d;
        }
    free(p);
    double m[2], e[2];
    for (int a = 0; a < 2; a++)
        m[a] = s[a] / STEPS, e[a] = sqrt((q[a] / STEPS - m[a] * m[a]) / STEPS);
    *r = m[0] / m[1];
    *se = ratio_se(m[0], e[0], m[1], e[1]);
}

/* Thesis §4.1 on Figure 4.1, from l_x / l_y of each run (ratio[v * seeds + s]) and the steps of
 * step_ratio. "About the aspect ratio" is read as within ±25 % (the ledger's margin for "about", as
 * in fig4.5) and shown at ±10 % too: the noise's shape is the harness's reading of T2, which is about
 * the step; "isotropic" as within ±10 % of 1. */
static char *claims(const struct fig41 *t, char *err, size_t errlen)
{
    const double *ratio = t->q[Q_RATIO], aspect = (double)t->res[0] / t->res[1];
    int seeds = t->seeds;
    const char *out = t->fo.out, *scale = t->fo.scale;
    struct claims cl;
    char command[64], zs[128], md[256];
    snprintf(command, sizeof command, "make fig4.1 SCALE=%s", scale);
    claims_begin(&cl, scale, command, "Claims of thesis §4.1 on Fig. 4.1, %d seeds, aspect ratio %.3g", seeds, aspect);
    double m[NVAR], se[NVAR];
    for (int v = 0; v < NVAR; v++)
        mean_se(ratio + v * seeds, seeds, &m[v], &se[v]);
    const char *src = "thesis §4.1, Fig. 4.1";
    double sr, srse;
    step_ratio(t->res[0], t->res[1], t->fo.seed, &sr, &srse);
    struct verdict sv = verdict_similar(sr, srse, 2, 0, 0.25, 1);
    snprintf(zs, sizeof zs, "2x=%.2f", sv.zmin);
    snprintf(md, sizeof md, "2 within ±25 %% (z = %.1f; %d steps, aspect ratio %.3g)", sv.zmin, STEPS, aspect);
    claims_row(&cl, "T2", "thesis §4.1", "isotropic small steps move about twice as far horizontally",
               "mean step in pixels, x over y", "iso", sr, srse, zs, md, &sv);
    /* stretched: the isotropic kernel's ratio above 1 (a constant, se 0) */
    struct verdict v = verdict_pair(m[0], se[0], 1, 0, +1, seeds);
    claims_row_against(&cl, "T1", src, "isotropic small steps stretch the noise horizontally", "l_x / l_y", "iso", m[0],
                       se[0], &v, "1", "1");
    const double margin[2] = {0.25, 0.10};
    for (int i = 0; i < 2; i++) {
        v = verdict_similar(m[0], se[0], aspect, 0, margin[i], seeds);
        char against[32];
        snprintf(against, sizeof against, "aspect%.0f%%", 100 * margin[i]);
        claims_row_against(&cl, "harness:T2", src, "by about the aspect ratio", "l_x / l_y", "iso", m[0], se[0], &v,
                           against, "aspect ratio %.3g within ±%.0f %%", aspect, 100 * margin[i]);
    }
    v = verdict_similar(m[1], se[1], 1, 0, 0.10, seeds);
    claims_row_against(&cl, "T3", src, "resolution-aware steps make the noise isotropic", "l_x / l_y", "rap", m[1],
                       se[1], &v, "1", "1 within ±10 %%");
    return claims_finish(&cl, out, err, errlen);
}

static void parse(struct fig41 *t, int argc, char **argv)
{
    const struct opt opts[] = {
        OPTS_FIGURE(t->fo, "scenes/wall/scene.json", "results/fig4.1"),
        OPT_RESOLUTION(t->res, .lo = 8, .hi = 1 << 14, .help = "image size", .def = "320x180", .paper = "640x360"),
        OPT_MPP(t->mpp, .lo = 0.01, .hi = 1e6, .help = "PSSMLT mutations per pixel", .def = "8", .paper = "64"),
        OPT_SEEDS(t->seeds, .help = "runs per variant, seeds S..S+N-1", .def = "16", .paper = "16"),
        OPT_P_LARGE(t->p_large),
        {"--max-lag", OPT_INT, OPT_DST(t->maxlag), .arg = "L", .lo = 2, .hi = 4096,
         .help = "autocorrelation lags 0..L pixels", .def = "40"},
        OPTS_REFERENCE(t->refpath, t->refspp, "PT", "results/reference/wall-pt-WxH-SPP.exr", "64", "1024"),
        {0}};
    opts_parse(&(struct opts_spec){.prog = prog, .usage = "usage: fig4_1 [options]\n", .opts = opts, .fig = &t->fo},
               argc, argv);
    if (t->maxlag >= t->res[0] || t->maxlag >= t->res[1])
        opts_fail(prog, "--max-lag %d: must be below the image's width and height", t->maxlag);
    opts_require_image_input(prog);
    snprintf(t->defref, sizeof t->defref, "results/reference/wall-pt-%dx%d-%d.exr", t->res[0], t->res[1], t->refspp);
    if (!t->refpath) t->refpath = t->defref;
}

/* Both variants over the seeds; the first seed's render and error image of each. */
static bool run(struct fig41 *t, char *err, size_t errlen)
{
    const struct opts_figure *fo = &t->fo;
    int L = t->maxlag + 1, seeds = t->seeds;
    struct wall_cfg cfg = {.p_large = t->p_large,
                           .mpp = t->mpp,
                           .seed_paths = fo->paper ? 1000000 : 100000,
                           .threads = fo->threads,
                           .maxlag = t->maxlag};
    for (int i = 0; i < NQ; i++)
        t->q[i] = xcalloc((size_t)NVAR * seeds, sizeof(double));
    t->evar = xcalloc((size_t)NVAR * seeds, sizeof *t->evar);
    t->rx = xcalloc((size_t)NVAR * seeds * L, sizeof *t->rx), t->ry = xcalloc((size_t)NVAR * seeds * L, sizeof *t->ry);
    double range = 0;
    for (int v = 0; v < NVAR; v++) {
        cfg.rap = v == 1;
        for (int s = 0; s < seeds; s++) {
            fprintf(stderr, "%s: %s, seed %llu (%d of %d)\n", prog, names[v], (unsigned long long)(fo->seed + s), s + 1,
                    seeds);
            struct wall_meas m;
            struct image *img = wall_run(t->sc, &cfg, fo->seed + s, t->ref, &m, err, errlen);
            if (!img) return false;
            int k = v * seeds + s;
            double *const *q = t->q;
            q[Q_LX][k] = m.lx, q[Q_LY][k] = m.ly, q[Q_RATIO][k] = m.lx / m.ly, q[Q_RHO1X][k] = m.rho1_x;
            q[Q_RHO1Y][k] = m.rho1_y, q[Q_RELMSE][k] = m.relmse, q[Q_ACCEPT][k] = m.accept;
            t->evar[k] = m.err_var;
            memcpy(t->rx + (size_t)k * L, m.rho_x, L * sizeof(double));
            memcpy(t->ry + (size_t)k * L, m.rho_y, L * sizeof(double));
            bool ok = true;
            if (s == 0) {
                char path[4096];
                snprintf(path, sizeof path, "%s/error-%s.png", fo->out, names[v]);
                ok = ch4_write_pair(img, fo->out, names[v], err, errlen) &&
                     ch4_write_error_png(m.err, t->res[0], t->res[1], &range, path, err, errlen);
            }
            wall_meas_free(&m);
            img_destroy(img);
            if (!ok) return false;
        }
    }
    return true;
}

/* A row of OUT/fig4.1-runs.csv (the seed as unsigned: COL_LONG's "%lu") and of
 * OUT/fig4.1-profiles.csv. */
struct run_row {
    const char *variant;
    long seed;
    double q[NQ], error_var;
};
struct profile_row {
    const char *variant;
    int lag;
    double rho_x, rho_x_se, rho_y, rho_y_se;
};
static const struct column stat_cols[] = {
    COL_STRING(struct ch4_stat_row, "variant", config), COL_STRING(struct ch4_stat_row, "quantity", quantity),
    COL_INT(struct ch4_stat_row, "seeds", "%d", seeds), COL_DOUBLE(struct ch4_stat_row, "mean", "%.6g", mean),
    COL_DOUBLE(struct ch4_stat_row, "se", "%.6g", se),  {0}};
static const struct column profile_cols[] = {COL_STRING(struct profile_row, "variant", variant),
                                             COL_INT(struct profile_row, "lag", "%d", lag),
                                             COL_DOUBLE(struct profile_row, "rho_x", "%.6g", rho_x),
                                             COL_DOUBLE(struct profile_row, "rho_x_se", "%.6g", rho_x_se),
                                             COL_DOUBLE(struct profile_row, "rho_y", "%.6g", rho_y),
                                             COL_DOUBLE(struct profile_row, "rho_y_se", "%.6g", rho_y_se),
                                             {0}};

/* The metadata lines of all three tables. */
static void write_meta(FILE *f, const void *ctx)
{
    const struct fig41 *t = ctx;
    const struct opts_figure *fo = &t->fo;
    csv_meta_head(f, "fig4.1: PSSMLT small steps on a 16:9 diffuse wall, isotropic (iso) vs resolution-aware (rap)",
                  fo->scene, fo->scale);
    csv_meta(f, "resolution", "%dx%d", t->res[0], t->res[1]);
    csv_meta(f, "mutations_per_pixel", "%g", t->mpp);
    csv_meta(f, "p_large", "%g", t->p_large);
    csv_meta(f, "kernel", "kelemen s1 1/1024 s2 1/64");
    ch4_meta_runs(f, fo->seed, t->seeds, fo->threads);
    csv_meta(f, "reference", "%s (PT %d spp); its pixel-noise variance %.4g", t->refpath, t->refspp, t->ref_var);
    csv_meta(f, NULL,
             "error e = lum(s*I - R), s = mean lum R / mean lum I; rho = normalised autocorrelation of e;"
             " l_x, l_y = lag where rho(d) / rho(1) falls below 1/e (pixels); rho1 = rho(1)");
}

/* Variant v's profile row at lag d: mean and standard error over the seeds of rho_x and rho_y. */
static void profile_row(const struct fig41 *t, int v, int d, double *tmp, struct profile_row *row)
{
    int L = t->maxlag + 1, seeds = t->seeds;
    *row = (struct profile_row){.variant = names[v], .lag = d};
    for (int s = 0; s < seeds; s++)
        tmp[s] = t->rx[(size_t)(v * seeds + s) * L + d];
    mean_se(tmp, seeds, &row->rho_x, &row->rho_x_se);
    for (int s = 0; s < seeds; s++)
        tmp[s] = t->ry[(size_t)(v * seeds + s) * L + d];
    mean_se(tmp, seeds, &row->rho_y, &row->rho_y_se);
}

/* The rows of the three tables: per run (runs), mean and se per quantity (stats), autocorrelation
 * profiles (profiles). */
static void write_rows(const struct fig41 *t, struct table *runs, struct table *stats, struct table *profiles)
{
    int seeds = t->seeds;
    double *tmp = xmalloc(seeds * sizeof *tmp);
    for (int v = 0; v < NVAR; v++) {
        for (int s = 0; s < seeds; s++) {
            int k = v * seeds + s;
            struct run_row row = {names[v], (long)(t->fo.seed + s), .error_var = t->evar[k]};
            for (int i = 0; i < NQ; i++)
                row.q[i] = t->q[i][k];
            table_row(runs, &row);
        }
        for (int i = 0; i < NQ; i++) {
            struct ch4_stat_row row = {.config = names[v], .quantity = qn[i]};
            ch4_stat_row_of(&row, t->q[i] + v * seeds, seeds);
            table_row(stats, &row);
        }
        for (int d = 0; d <= t->maxlag; d++) {
            struct profile_row row;
            profile_row(t, v, d, tmp, &row);
            table_row(profiles, &row);
        }
    }
    free(tmp);
}

/* OUT/fig4.1-runs.csv, fig4.1.csv and fig4.1-profiles.csv, with the same metadata. */
static bool write_tables(const struct fig41 *t, char *err, size_t errlen)
{
    struct column run_cols[NQ + 4] = {COL_STRING(struct run_row, "variant", variant),
                                      COL_LONG(struct run_row, "seed", "%lu", seed)};
    table_columns(run_cols + 2, NQ, qn, COL_D, offsetof(struct run_row, q), sizeof(double), "%.6g");
    run_cols[NQ + 2] = (struct column)COL_DOUBLE(struct run_row, "error_var", "%.6g", error_var);
    run_cols[NQ + 3] = (struct column){0};
    struct table_set tb;
    table_set_open(&tb, 3, (const char *[]){"fig4.1-runs.csv", "fig4.1.csv", "fig4.1-profiles.csv"},
                   (const struct column *[]){run_cols, stat_cols, profile_cols}, write_meta, t);
    write_rows(t, &tb.t[0], &tb.t[1], &tb.t[2]);
    return table_set_save(&tb, prog, t->fo.out, err, errlen);
}

int main(int argc, char **argv)
{
    struct fig41 t = {0};
    parse(&t, argc, argv);
    char err[1024];
    t.sc = opts_figure_scene(&t.fo);
    camera_resize(&t.sc->cam, t.res[0], t.res[1]);
    t.ref = ch4_reference(t.sc, METHOD_PT, t.refspp, t.refpath, t.fo.threads, prog, err, sizeof err);
    bool ok = t.ref && ch4_write_pair(t.ref, t.fo.out, "reference", err, sizeof err);
    if (ok) t.ref_var = ch4_pixel_noise_var(t.ref);
    ok = ok && run(&t, err, sizeof err) && write_tables(&t, err, sizeof err);
    ok = ok && ch4_show_claims(claims(&t, err, sizeof err));
    for (int i = 0; i < NQ; i++)
        free(t.q[i]);
    free(t.evar), free(t.rx), free(t.ry);
    img_destroy(t.ref);
    scene_free(t.sc);
    if (!ok) die(DIE_RUNTIME, prog, "%s", err);
    return 0;
}
