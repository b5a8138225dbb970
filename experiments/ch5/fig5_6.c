/* bin/fig5_6: thesis Figure 5.6. Rendered images of scenes/jewelry with p_large = 0.01 (small
 * steps do nearly all the exploring): MMLT small steps vs controlled small steps (Alg. 4), equal
 * mutation counts, the same Gaussian kernel (sigma 1/64), beside a BDPT reference (cached as
 * results/reference/jewelry-bdpt-<spp>-<W>x<H>.exr). Writes to OUT: reference.png, mmlt.png,
 * controlled.png (first seed), fig5.6.csv (kind,relmse,stderr,seeds,accept_small,
 * mutations_per_second,corrlen,corrlen_se,blur8,blur8_se: relMSE = mean over pixels and channels of
 * (I - R)^2 / (R^2 + 0.01); corrlen, blur8 the error's correlation length in pixels and its share
 * in 8x8 blobs, below; each averaged over seeds with its standard error over seeds) and
 * claims.csv, claims.md: the thesis's claims with their verdicts. */
#include "ch5/fig5_common.h"
#include "common/claims.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/refcache.h"
#include "mc/render.h"
#include "path/scene_ready.h"
#include "scene/scene_hash.h"
#include "stats/noise_corr.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* What the reference's render needs (refcache_render_fn's ctx). */
struct ref_job {
    const struct scene *sc;
    const struct fig5_cfg *c;
    int spp;
};

/* refcache_render_fn: the BDPT reference at seed 777, written to path. */
static struct image *render_reference(void *ctx, const char *path, char *err, size_t errlen)
{
    const struct ref_job *j = ctx;
    fprintf(stderr, "fig5_6: rendering the BDPT reference (%d spp) into %s\n", j->spp, path);
    struct render_opts o = {.method = METHOD_BDPT,
                            .spp = j->spp,
                            .seed = 777,
                            .threads = j->c->fig.threads,
                            .max_length = j->c->max_length};
    struct render_stats st;
    struct image *ref = render_mc(j->sc, &o, &st);
    if (!img_write_exr(ref, 1.0, path, err, errlen)) {
        img_destroy(ref);
        return NULL;
    }
    return ref;
}

/* The BDPT reference, rendered once per size and kept under results/reference/ by
 * common/refcache.h's rule (keyed by the scene's content and the render's settings). */
static struct image *reference(const struct scene *sc, const struct fig5_cfg *c, int spp)
{
    char path[4096], err[4200], settings[256];
    snprintf(path, sizeof path, "results/reference/jewelry-bdpt-%d-%dx%d.exr", spp, c->width, c->height);
    snprintf(settings, sizeof settings, "bdpt spp=%d seed=777 max_length=%d resolution=%dx%d", spp, c->max_length,
             c->width, c->height);
    struct refcache rc = {.path = path, .scene_hash = ckpt_scene_hash(sc), .settings = settings};
    struct image *ref = refcache_get(&rc, render_reference, &(struct ref_job){sc, c, spp}, err, sizeof err);
    if (!ref) die(DIE_RUNTIME, "fig5_6", "%s", err);
    return ref;
}

/* Thesis §5.3 on Fig. 5.6: controlled small steps are not better (their relMSE is the larger) and
 * their noise is streaky and splotchy (the longer error correlation length, the larger share of the
 * error in 8 x 8 blobs). */
enum { Q_RELMSE, Q_CORRLEN, Q_BLUR8, NQ };
static void write_claims(const struct fig5_cfg *c, double mean[2][NQ], double se[2][NQ])
{
    static const char *const claim[NQ] = {"controlled small steps are not better than MMLT's (worse noise)",
                                          "controlled small steps give streaky, splotchy noise",
                                          "controlled small steps give streaky, splotchy noise"};
    static const char *const stat[NQ] = {"relMSE against BDPT", "error correlation length (pixels)",
                                         "error share surviving an 8x8 blur"};
    struct claims cl;
    char command[64], zs[128], md[256];
    snprintf(command, sizeof command, "make fig5.6 SCALE=%s", c->fig.scale);
    claims_begin(&cl, c->fig.scale, command,
                 "Claims of thesis §5.3 (Fig. 5.6) on %s at %dx%d, %ld mutations per pixel, %d seeds", c->fig.scene,
                 c->width, c->height, c->mpp, c->seeds);
    const bool both[2] = {true, true};
    for (int q = 0; q < NQ; q++) {
        double m[2] = {mean[0][q], mean[1][q]}, s[2] = {se[0][q], se[1][q]}, z[2];
        struct verdict v = verdict_extreme(m, s, both, 2, 1, +1, c->seeds, z);
        snprintf(zs, sizeof zs, "mmlt=%.2f", z[0]);
        snprintf(md, sizeof md, "mmlt %.4g ± %.2g (z = %.1f)", m[0], s[0], z[0]);
        claims_row(&cl, "thesis §5.3", claim[q], stat[q], "controlled", m[1], s[1], zs, md, &v);
    }
    claims_finish_print(&cl, c->fig.out);
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
    if (!img_write_png(ref, 1.0, path, err, sizeof err)) return fprintf(stderr, "%s\n", err), 1;
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    char title[256];
    snprintf(title, sizeof title,
             "fig5.6: relMSE against BDPT, MMLT vs controlled small steps, p_large %g, Gaussian sigma 1/64", c.p_large);
    fig5_meta_head(f, &c, title);
    csv_meta(f, "reference_spp", "%d", spp);
    fig5_meta_runs(f, &c);
    fprintf(f, "kind,relmse,stderr,seeds,accept_small,mutations_per_second,corrlen,corrlen_se,blur8,blur8_se\n");
    double mean[2][NQ], se[2][NQ];
    double *x = xmalloc(sizeof *x * NQ * (size_t)c.seeds);
    for (int kind = 0; kind < 2; kind++) {
        double acc = 0, rate = 0;
        for (int i = 0; i < c.seeds; i++) {
            struct mlt_result r;
            fig5_run(sc, &c, kind ? SMALL_STEP_CONTROLLED : SMALL_STEP_PSS, c.fig.seed + (uint64_t)i, false, &r);
            x[i] = img_relmse(r.img, ref, 0.01);
            x[c.seeds + i] = error_corr_length(r.img, ref);
            x[2 * c.seeds + i] = error_blur_share(r.img, ref, 0.01, 8);
            acc += cell_mean(&r.stats.total[PROPOSAL_SMALL]) / c.seeds;
            rate += r.mutations / r.seconds / c.seeds;
            if (i == 0) {
                snprintf(path, sizeof path, "%s/%s.png", c.fig.out, fig5_kind_name[kind]);
                if (!img_write_png(r.img, 1.0, path, err, sizeof err)) return fprintf(stderr, "%s\n", err), 1;
                snprintf(path, sizeof path, "%s/%s.exr", c.fig.out, fig5_kind_name[kind]);
                if (!img_write_exr(r.img, 1.0, path, err, sizeof err)) return fprintf(stderr, "%s\n", err), 1;
            }
            mlt_result_free(&r);
        }
        for (int q = 0; q < NQ; q++)
            mean_se(x + (size_t)q * c.seeds, c.seeds, &mean[kind][q], &se[kind][q]);
        fprintf(f, "%s,%.9g,%.9g,%d,%.6f,%.0f,%.6g,%.3g,%.6g,%.3g\n", fig5_kind_name[kind], mean[kind][0], se[kind][0],
                c.seeds, acc, rate, mean[kind][1], se[kind][1], mean[kind][2], se[kind][2]);
    }
    free(x);
    fclose(f);
    fig5_write_text(&c, "fig5.6.csv", buf);
    free(buf);
    write_claims(&c, mean, se);
    img_destroy(ref);
    scene_free(sc);
    return 0;
}
