/* bin/fig5_6: thesis Figure 5.6. Rendered images of scenes/jewelry with p_large = 0.01 (small
 * steps do nearly all the exploring): MMLT small steps vs controlled small steps (Alg. 4), equal
 * mutation counts, the same Gaussian kernel (sigma 1/64), beside a BDPT reference (cached as
 * results/reference/jewelry-bdpt-<spp>-<W>x<H>.exr). Writes to OUT: reference.png, mmlt.png,
 * controlled.png (first seed), fig5.6.csv (kind,relmse,stderr,seeds,accept_small,
 * mutations_per_second,corrlen,corrlen_se,blur8,blur8_se,block_median_relmse,block_median_relmse_se,
 * trimmed_relmse,trimmed_relmse_se,median_slope,median_slope_se: relMSE = mean over pixels and channels of (I - R)^2 /
 * (R^2 + 0.01); corrlen, blur8 the error's correlation length in pixels and its share in 8x8 blobs, below; the median
 * of the 16x16 blocks' relMSE and the relMSE without the 0.1 % largest pixel errors, the firefly-robust relMSEs of
 * chapter 6; median_slope,median_slope_se: the slope of log median block relMSE against log mutations from a run of a
 * quarter of the mutations (same seed) to the full one; glossy_corrlen, glossy_blur4 (and _se): the correlation length
 * and the share in 4x4 blobs over the pixels that show the rings (glossy first hits); each averaged over seeds with
 * its standard error over seeds)
 * and claims.csv, claims.md: the thesis's claims with their verdicts. */
#include "ch5/fig5_common.h"
#include "common/claims.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/glossy_mask.h"
#include "common/reference.h"
#include "mc/render.h"
#include "path/scene_ready.h"
#include "stats/error_stats.h"
#include "stats/noise_corr.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The BDPT reference, rendered once per size and kept under results/reference/ by
 * common/reference.h's rule (keyed by the scene's content and the render's settings). */
static struct image *reference(const struct scene *sc, const struct fig5_cfg *c, int spp)
{
    char path[4096], err[4200];
    snprintf(path, sizeof path, "results/reference/jewelry-bdpt-%d-%dx%d.exr", spp, c->width, c->height);
    struct reference_spec spec = {.path = path,
                                  .method = METHOD_BDPT,
                                  .spp = spp,
                                  .seed = 777,
                                  .max_length = c->max_length,
                                  .threads = c->fig.threads};
    struct image *ref = reference_render_cached(c->prog, sc, &spec, err, sizeof err);
    if (!ref) die(DIE_RUNTIME, c->prog, "%s", err);
    return ref;
}

/* Thesis §5.3 on Fig. 5.6: controlled small steps are not better (their relMSE is the larger) and
 * their noise is streaky and splotchy (the longer error correlation length, the larger share of the
 * error in 8 x 8 blobs). The thesis places the streaks "on top of the left ring" and the splotches
 * on the rings' glossy caustics, so T27 is measured on the pixels that show the rings (the glossy
 * first hits, common/glossy_mask.h); over the whole image it is the harness's reading. */
enum { Q_RELMSE, Q_CORRLEN, Q_BLUR8, Q_MEDIAN, Q_TRIMMED, Q_SLOPE, Q_GLOSSY_CORRLEN, Q_GLOSSY_BLUR4, NQ };
static void write_claims(const struct fig5_cfg *c, double mean[2][NQ], double se[2][NQ])
{
    static const char *const claim[NQ] = {"controlled small steps are not better than MMLT's (worse noise)",
                                          "controlled small steps give streaky, splotchy noise",
                                          "controlled small steps give streaky, splotchy noise",
                                          "controlled small steps are not better than MMLT's (worse noise)",
                                          "controlled small steps are not better than MMLT's (worse noise)",
                                          "controlled steps' artifacts disappear over time, but much more slowly",
                                          "controlled small steps give streaky, splotchy noise on the rings",
                                          "controlled small steps give streaky, splotchy noise on the rings"};
    /* T26 is about streaks and splotches, not fireflies: the firefly-robust relMSEs (the median of the
     * 16 x 16 blocks' and the relMSE without the 0.1 % largest pixel errors) decide it; the relMSE,
     * which isolated bright pixels can carry, is the harness's reading */
    static const char *const id[NQ] = {"harness:T26", "harness:T27", "harness:T27", "T26", "T26", "T28", "T27", "T27"};
    static const char *const stat[NQ] = {"relMSE against BDPT",
                                         "error correlation length (pixels)",
                                         "error share surviving an 8x8 blur",
                                         "median 16x16-block relMSE (firefly-robust)",
                                         "relMSE without the 0.1% largest pixel errors",
                                         "slope of log median block relMSE against log mutations (larger: slower)",
                                         "error correlation length on the rings' (glossy) pixels",
                                         "error share surviving a 4x4 blur on the rings' (glossy) pixels"};
    struct claims cl;
    char command[64];
    snprintf(command, sizeof command, "make fig5.6 SCALE=%s", c->fig.scale);
    claims_begin(&cl, c->fig.scale, command,
                 "Claims of thesis §5.3 (Fig. 5.6) on %s at %dx%d, %ld mutations per pixel, %d seeds", c->fig.scene,
                 c->width, c->height, c->mpp, c->seeds);
    for (int q = 0; q < NQ; q++) {
        struct verdict v = verdict_pair(mean[1][q], se[1][q], mean[0][q], se[0][q], +1, c->seeds);
        claims_row_against(&cl, id[q], "thesis §5.3", claim[q], stat[q], "controlled", mean[1][q], se[1][q], &v, "mmlt",
                           "mmlt %.4g ± %.2g", mean[0][q], se[0][q]);
    }
    claims_finish_print(&cl, c->fig.out);
}

/* A row of OUT/fig5.6.csv: one small-step kind over the seeds. */
struct kind_row {
    const char *kind;
    double relmse, relmse_se;
    int seeds;
    double accept_small, mutations_per_second, corrlen, corrlen_se, blur8, blur8_se;
    double median, median_se, trimmed, trimmed_se, slope, slope_se;
    double glossy_corrlen, glossy_corrlen_se, glossy_blur4, glossy_blur4_se;
};
static const struct column kind_cols[] = {
    COL_STRING(struct kind_row, "kind", kind),
    COL_DOUBLE(struct kind_row, "relmse", "%.9g", relmse),
    COL_DOUBLE(struct kind_row, "stderr", "%.9g", relmse_se),
    COL_INT(struct kind_row, "seeds", "%d", seeds),
    COL_DOUBLE(struct kind_row, "accept_small", "%.6f", accept_small),
    COL_DOUBLE(struct kind_row, "mutations_per_second", "%.0f", mutations_per_second),
    COL_DOUBLE(struct kind_row, "corrlen", "%.6g", corrlen),
    COL_DOUBLE(struct kind_row, "corrlen_se", "%.3g", corrlen_se),
    COL_DOUBLE(struct kind_row, "blur8", "%.6g", blur8),
    COL_DOUBLE(struct kind_row, "blur8_se", "%.3g", blur8_se),
    COL_DOUBLE(struct kind_row, "block_median_relmse", "%.6g", median),
    COL_DOUBLE(struct kind_row, "block_median_relmse_se", "%.3g", median_se),
    COL_DOUBLE(struct kind_row, "trimmed_relmse", "%.6g", trimmed),
    COL_DOUBLE(struct kind_row, "trimmed_relmse_se", "%.3g", trimmed_se),
    COL_DOUBLE(struct kind_row, "median_slope", "%.4g", slope),
    COL_DOUBLE(struct kind_row, "median_slope_se", "%.3g", slope_se),
    COL_DOUBLE(struct kind_row, "glossy_corrlen", "%.6g", glossy_corrlen),
    COL_DOUBLE(struct kind_row, "glossy_corrlen_se", "%.3g", glossy_corrlen_se),
    COL_DOUBLE(struct kind_row, "glossy_blur4", "%.6g", glossy_blur4),
    COL_DOUBLE(struct kind_row, "glossy_blur4_se", "%.3g", glossy_blur4_se),
    {0}};

/* OUT/NAME.png and .exr of a run. */
static void write_image(const struct fig5_cfg *c, const struct image *img, const char *name)
{
    char err[1024], path[4096];
    snprintf(path, sizeof path, "%s/%s.png", c->fig.out, name);
    if (!img_write_png(img, 1.0, path, err, sizeof err)) die(DIE_RUNTIME, c->prog, "%s", err);
    snprintf(path, sizeof path, "%s/%s.exr", c->fig.out, name);
    if (!img_write_exr(img, 1.0, path, err, sizeof err)) die(DIE_RUNTIME, c->prog, "%s", err);
}

/* The median of the image's 16 x 16-block relMSEs against ref (chapter 6's firefly-robust relMSE). */
static double median_block_relmse(const struct image *a, const struct image *ref)
{
    int cap = (a->w / 16) * (a->h / 16);
    double *v = xmalloc(sizeof *v * (size_t)(cap > 0 ? cap : 1));
    double m = median_of(v, block_relmse(a, ref, 16, 0.01, v, cap));
    free(v);
    return m;
}

/* Thesis §5.3.3 (T28): how fast a kind's artifacts fade. The same seed at a quarter of the
 * mutations; the slope of log median block relMSE (firefly-robust) against log mutations from there
 * to the full run, whose value is `full` (-1: error falling as 1 / mutations). */
static double decay_slope(const struct scene *sc, const struct fig5_cfg *c, int kind, uint64_t seed,
                          const struct image *ref, double full)
{
    struct fig5_cfg q = *c;
    q.mpp = c->mpp / 4 > 0 ? c->mpp / 4 : 1;
    struct mlt_result r;
    fig5_run(sc, &q, kind ? SMALL_STEP_CONTROLLED : SMALL_STEP_PSS, seed, false, &r);
    double quarter = median_block_relmse(r.img, ref);
    mlt_result_free(&r);
    return log(full / quarter) / log((double)c->mpp / q.mpp);
}

/* One small-step kind over the seeds against ref (glossy: the rings' pixels): its row of
 * OUT/fig5.6.csv, its means and standard errors (x: room for NQ values per seed), the first seed's image. */
static void run_kind(const struct scene *sc, const struct fig5_cfg *c, const struct image *ref, const bool *glossy,
                     int kind, double *x, double mean[NQ], double se[NQ], struct table *t)
{
    double acc = 0, rate = 0;
    for (int i = 0; i < c->seeds; i++) {
        struct mlt_result r;
        fig5_run(sc, c, kind ? SMALL_STEP_CONTROLLED : SMALL_STEP_PSS, c->fig.seed + (uint64_t)i, false, &r);
        x[Q_RELMSE * c->seeds + i] = img_relmse(r.img, ref, 0.01);
        x[Q_CORRLEN * c->seeds + i] = error_corr_length(r.img, ref);
        x[Q_BLUR8 * c->seeds + i] = error_blur_share(r.img, ref, 0.01, 8);
        x[Q_MEDIAN * c->seeds + i] = median_block_relmse(r.img, ref);
        x[Q_TRIMMED * c->seeds + i] = trimmed_relmse(r.img, ref, 0.01, 0.001);
        x[Q_SLOPE * c->seeds + i] =
            decay_slope(sc, c, kind, c->fig.seed + (uint64_t)i, ref, x[Q_MEDIAN * c->seeds + i]);
        x[Q_GLOSSY_CORRLEN * c->seeds + i] = error_corr_length_in(r.img, ref, glossy);
        x[Q_GLOSSY_BLUR4 * c->seeds + i] = error_blur_share_in(
            r.img, ref, 0.01, 4, (const int[4]){0, 0, ref->w, ref->h}, glossy, mean_lum_scale(r.img, ref));
        acc += cell_mean(&r.stats.total[PROPOSAL_SMALL]) / c->seeds;
        rate += r.mutations / r.seconds / c->seeds;
        if (i == 0) write_image(c, r.img, fig5_kind_name[kind]);
        mlt_result_free(&r);
    }
    for (int q = 0; q < NQ; q++)
        mean_se(x + (size_t)q * c->seeds, c->seeds, &mean[q], &se[q]);
    table_row(t, &(struct kind_row){fig5_kind_name[kind],
                                    mean[Q_RELMSE],
                                    se[Q_RELMSE],
                                    c->seeds,
                                    acc,
                                    rate,
                                    mean[Q_CORRLEN],
                                    se[Q_CORRLEN],
                                    mean[Q_BLUR8],
                                    se[Q_BLUR8],
                                    mean[Q_MEDIAN],
                                    se[Q_MEDIAN],
                                    mean[Q_TRIMMED],
                                    se[Q_TRIMMED],
                                    mean[Q_SLOPE],
                                    se[Q_SLOPE],
                                    mean[Q_GLOSSY_CORRLEN],
                                    se[Q_GLOSSY_CORRLEN],
                                    mean[Q_GLOSSY_BLUR4],
                                    se[Q_GLOSSY_BLUR4]});
}

int main(int argc, char **argv)
{
    struct fig5_cfg c = {.prog = "fig5_6", .fig.out = "results/fig5.6", .p_large = 0.01};
    fig5_parse(argc, argv, &c, "The BDPT reference: 1024 spp at --scale quick, 16384 at paper.\n");
    struct scene *sc = fig5_scene(&c);
    int spp = !strcmp(c.fig.scale, "paper") ? 16384 : 1024;
    struct image *ref = reference(sc, &c, spp);
    char err[1024], path[4096];
    snprintf(path, sizeof path, "%s/reference.png", c.fig.out);
    if (!img_write_png(ref, 1.0, path, err, sizeof err)) die(DIE_RUNTIME, c.prog, "%s", err);
    struct table_set ts;
    FILE *f = table_set_open_one(&ts, "fig5.6.csv", kind_cols);
    if (f) {
        char title[256];
        snprintf(title, sizeof title,
                 "fig5.6: relMSE against BDPT, MMLT vs controlled small steps, p_large %g, Gaussian sigma 1/64",
                 c.p_large);
        fig5_meta_head(f, &c, title);
        csv_meta(f, "reference_spp", "%d", spp);
        fig5_meta_runs(f, &c);
    }
    int nglossy;
    bool *glossy = glossy_mask(sc, &nglossy);
    if (f) csv_meta(f, "glossy_pixels", "%d", nglossy);
    double mean[2][NQ], se[2][NQ];
    double *x = xmalloc(sizeof *x * NQ * (size_t)c.seeds);
    for (int kind = 0; kind < 2; kind++)
        run_kind(sc, &c, ref, glossy, kind, x, mean[kind], se[kind], &ts.t[0]);
    free(x);
    free(glossy);
    fig5_save_tables(&c, &ts);
    write_claims(&c, mean, se);
    img_destroy(ref);
    scene_free(sc);
    return 0;
}
