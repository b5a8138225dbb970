/* bin/fig5_5: thesis Figure 5.5. The mean angle change (Eq. 5.38-5.39, core/stats/angle_change.h) that
 * MMLT small steps and controlled small steps (Alg. 4) introduce, per pixel of the current path,
 * and for the analysis the root perturbation alone (Alg. 3, whose chain is not unbiased), on
 * scenes/jewelry: same mutation count, same Gaussian kernel (sigma 1/64), p_large 0.1, `seeds`
 * independent runs of each. Writes to OUT:
 *   mmlt/controlled/root.angle.exr         mean over seeds of each run's per-pixel mean (radians)
 *   mmlt/controlled/root.angle.png         grey linear in it, black 0, white >= 0.5 rad
 *   edges.png                              the edge mask (white: within 2 px of an edge)
 *   fig5.5.csv   kind,region,mean,stderr,seeds  (region all / edge / elsewhere: mean over the
 *                pixels of the region that saw a step; ratio: edge / elsewhere; stderr over seeds)
 *   fig5.5-lengths.csv  kind,length,steps,mean_dpsi,stderr  (steps pooled, stderr over seeds)
 *   claims.csv, claims.md   the thesis's claims on the edge / elsewhere ratio with their verdicts */
#include "base/util.h"
#include "ch5/edge_mask.h"
#include "ch5/fig5_common.h"
#include "common/claims.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "path/scene_ready.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { R_ALL, R_EDGE, R_ELSE, R_RATIO, REGIONS };
enum { NK = 3 }; /* small-step kinds, in enum small_step's order: MMLT's, controlled, root */
static const char *const region_name[REGIONS] = {"all", "edge", "elsewhere", "ratio"};

/* Thesis §5.3 on Fig. 5.5, tested on the edge / elsewhere ratio of the mean angle change (per seed,
 * then mean and standard error over seeds): MMLT's steps change paths more near edges (ratio above
 * 1), controlled steps less than MMLT's, and controlled steps show no halo, taken as a ratio within
 * ±25 % of 1 (the ledger's similarity margin, as in fig4.6). */
static void write_claims(const struct fig5_cfg *c, const double *ratio_mean, const double *ratio_se)
{
    struct claims cl;
    char command[64];
    snprintf(command, sizeof command, "make fig5.5 SCALE=%s", c->fig.scale);
    claims_begin(&cl, c->fig.scale, command,
                 "Claims of thesis §5.3 (Fig. 5.5) on %s at %dx%d, %ld mutations per pixel, %d seeds", c->fig.scene,
                 c->width, c->height, c->mpp, c->seeds);
    const char *stat = "mean angle change within 2 px of an edge / elsewhere";
    struct verdict v = verdict_pair(ratio_mean[0], ratio_se[0], 1, 0, +1, c->seeds);
    claims_row_against(&cl, "T24", "thesis §5.3", "MMLT small steps change the path more near edges (halos)", stat,
                       "mmlt", ratio_mean[0], ratio_se[0], &v, "no-edge-effect", "1, no edge effect");
    v = verdict_pair(ratio_mean[1], ratio_se[1], ratio_mean[0], ratio_se[0], -1, c->seeds);
    claims_row_against(&cl, "T25", "thesis §5.3", "controlled small steps are less sensitive to edges than MMLT's",
                       stat, "controlled", ratio_mean[1], ratio_se[1], &v, "mmlt", "mmlt %.4g ± %.2g", ratio_mean[0],
                       ratio_se[0]);
    v = verdict_similar(ratio_mean[1], ratio_se[1], 1, 0, 0.25, c->seeds);
    claims_row_against(&cl, "T25", "thesis §5.3", "controlled small steps show no halos at edges", stat, "controlled",
                       ratio_mean[1], ratio_se[1], &v, "1", "1 within ±25 %%");
    claims_finish_print(&cl, c->fig.out);
}

/* What the runs measure: per (kind, region, seed) the mean angle change (reg), per (kind, seed)
 * the mean per path length, per kind the small steps per path length. */
struct meas {
    double *reg;
    double (*len_mean)[MAX_PATH_LENGTH + 1];
    long len_steps[NK][MAX_PATH_LENGTH + 1];
};

/* OUT/edges.png: the edge mask, white on black. */
static void write_edges(const struct fig5_cfg *c, const bool *mask)
{
    char err[1024], path[4096];
    int W = c->width, H = c->height;
    struct image *mi = img_create(W, H);
    for (int i = 0; i < W * H; i++)
        if (mask[i]) img_add(mi, i % W, i / W, v3s(1));
    snprintf(path, sizeof path, "%s/edges.png", c->fig.out);
    if (!fig5_write_linear_png(mi, 1, path, err, sizeof err)) die(DIE_RUNTIME, c->prog, "%s", err);
    img_destroy(mi);
}

/* One small-step kind over the seeds: its region means into m, its mean angle image (averaged
 * over the seeds) to OUT/KIND.angle.exr and .png. */
static void run_kind(const struct fig5_cfg *c, struct scene *sc, const bool *mask, int kind, struct meas *m)
{
    int W = c->width, H = c->height;
    char err[1024], path[4096];
    struct image *avg = img_create(W, H);
    for (int s = 0; s < c->seeds; s++) {
        struct mlt_result r;
        fig5_run(sc, c, (enum small_step)kind, c->fig.seed + (uint64_t)s, true, &r);
        struct image *a = angle_acc_image(r.angle);
        img_accumulate(avg, a, 1.0 / c->seeds);
        double sum[3] = {0}, n[3] = {0};
        for (int i = 0; i < W * H; i++) {
            if (!(r.angle->count[i] > 0)) continue;
            double v = a->px[3 * i];
            sum[R_ALL] += v, n[R_ALL]++;
            sum[mask[i] ? R_EDGE : R_ELSE] += v, n[mask[i] ? R_EDGE : R_ELSE]++;
        }
        double *x = m->reg + ((size_t)kind * REGIONS) * c->seeds;
        for (int g = 0; g < 3; g++)
            x[g * c->seeds + s] = sum[g] / n[g];
        x[R_RATIO * c->seeds + s] = x[R_EDGE * c->seeds + s] / x[R_ELSE * c->seeds + s];
        for (int k = 1; k <= MAX_PATH_LENGTH; k++) {
            m->len_mean[kind * c->seeds + s][k] = r.angle->len[k].attempts ? cell_mean(&r.angle->len[k]) : NAN;
            m->len_steps[kind][k] += r.angle->len[k].attempts;
        }
        img_destroy(a);
        mlt_result_free(&r);
    }
    snprintf(path, sizeof path, "%s/%s.angle.exr", c->fig.out, fig5_kind_name[kind]);
    bool ok = img_write_exr(avg, 1.0, path, err, sizeof err);
    snprintf(path, sizeof path, "%s/%s.angle.png", c->fig.out, fig5_kind_name[kind]);
    if (!ok || !fig5_write_linear_png(avg, 0.5, path, err, sizeof err)) die(DIE_RUNTIME, c->prog, "%s", err);
    img_destroy(avg);
}

/* A row of OUT/fig5.5.csv and of OUT/fig5.5-lengths.csv. */
struct region_row {
    const char *kind, *region;
    double mean, se;
    int seeds;
};
static const struct column region_cols[] = {
    COL_STRING(struct region_row, "kind", kind),         COL_STRING(struct region_row, "region", region),
    COL_DOUBLE(struct region_row, "mean", "%.9g", mean), COL_DOUBLE(struct region_row, "stderr", "%.9g", se),
    COL_INT(struct region_row, "seeds", "%d", seeds),    {0}};
struct length_row {
    const char *kind;
    int length;
    long steps;
    double mean_dpsi, se;
};
static const struct column length_cols[] = {
    COL_STRING(struct length_row, "kind", kind),         COL_INT(struct length_row, "length", "%d", length),
    COL_LONG(struct length_row, "steps", "%ld", steps),  COL_DOUBLE(struct length_row, "mean_dpsi", "%.9g", mean_dpsi),
    COL_DOUBLE(struct length_row, "stderr", "%.9g", se), {0}};

/* OUT/fig5.5.csv (per kind and region); the edge / elsewhere ratio per kind into ratio_mean,
 * ratio_se. */
static void write_regions(const struct fig5_cfg *c, const struct meas *m, double *ratio_mean, double *ratio_se)
{
    struct table_set ts;
    FILE *f = table_set_open_one(&ts, "fig5.5.csv", region_cols);
    if (f) {
        fig5_meta_head(f, c,
                       "fig5.5: mean angle change per pixel, MMLT vs controlled small steps, Gaussian sigma 1/64");
        csv_meta(f, "p_large", "%g", c->p_large);
        fig5_meta_runs(f, c);
    }
    for (int kind = 0; kind < NK; kind++)
        for (int g = 0; g < REGIONS; g++) {
            struct region_row row = {fig5_kind_name[kind], region_name[g], .seeds = c->seeds};
            mean_se(m->reg + ((size_t)kind * REGIONS + g) * c->seeds, c->seeds, &row.mean, &row.se);
            table_row(&ts.t[0], &row);
            if (g == R_RATIO) ratio_mean[kind] = row.mean, ratio_se[kind] = row.se;
        }
    fig5_save_tables(c, &ts);
}

/* OUT/fig5.5-lengths.csv (per kind and path length, over the seeds that saw the length). */
static void write_lengths(const struct fig5_cfg *c, const struct meas *m)
{
    struct table_set ts;
    table_set_open_one(&ts, "fig5.5-lengths.csv", length_cols);
    for (int kind = 0; kind < NK; kind++)
        for (int k = 2; k <= c->max_length; k++) {
            double x[1000];
            int n = 0;
            for (int s = 0; s < c->seeds; s++)
                if (!isnan(m->len_mean[kind * c->seeds + s][k])) x[n++] = m->len_mean[kind * c->seeds + s][k];
            if (n < 2) continue;
            struct length_row row = {.kind = fig5_kind_name[kind], .length = k, .steps = m->len_steps[kind][k]};
            mean_se(x, n, &row.mean_dpsi, &row.se);
            table_row(&ts.t[0], &row);
        }
    fig5_save_tables(c, &ts);
}

int main(int argc, char **argv)
{
    struct fig5_cfg c = {.prog = "fig5_5", .fig.out = "results/fig5.5", .p_large = 0.1};
    fig5_parse(argc, argv, &c, NULL);
    struct scene *sc = fig5_scene(&c);
    bool *mask = edge_mask(sc, 2);
    write_edges(&c, mask);
    static struct meas m;
    m.reg = xcalloc((size_t)NK * REGIONS * c.seeds, sizeof *m.reg);
    m.len_mean = xcalloc((size_t)NK * c.seeds, sizeof *m.len_mean);
    for (int kind = 0; kind < NK; kind++)
        run_kind(&c, sc, mask, kind, &m);
    double ratio_mean[NK], ratio_se[NK];
    write_regions(&c, &m, ratio_mean, ratio_se);
    write_lengths(&c, &m);
    write_claims(&c, ratio_mean, ratio_se);
    free(m.reg);
    free(m.len_mean);
    free(mask);
    scene_free(sc);
    return 0;
}
