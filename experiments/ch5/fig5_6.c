/* bin/fig5_6: thesis Figure 5.6. Rendered images of scenes/jewelry with p_large = 0.01 (small
 * steps do nearly all the exploring): MMLT small steps vs controlled small steps (Alg. 4), equal
 * mutation counts, the same Gaussian kernel (sigma 1/64), beside a BDPT reference (cached as
 * results/reference/jewelry-bdpt-<spp>-<W>x<H>.exr). Writes to OUT: reference.png, mmlt.png,
 * controlled.png (first seed), and fig5.6.csv: kind,relmse,stderr,seeds with relMSE = mean over
 * pixels and channels of (I - R)^2 / (R^2 + 0.01), averaged over seeds, stderr over seeds. */
#include "ch5/fig5_common.h"
#include "common/csv_meta.h"
#include "mc/render.h"
#include "path/scene_ready.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* The BDPT reference, rendered once per size and kept under results/reference/. */
static struct image *reference(const struct scene *sc, const struct fig5_cfg *c, int spp)
{
    char path[4096], err[1024];
    mkdir("results", 0777);
    mkdir("results/reference", 0777);
    snprintf(path, sizeof path, "results/reference/jewelry-bdpt-%d-%dx%d.exr", spp, c->width, c->height);
    struct image *ref = img_read(path, err, sizeof err);
    if (ref && ref->w == c->width && ref->h == c->height) return ref;
    img_destroy(ref);
    fprintf(stderr, "fig5_6: rendering the BDPT reference (%d spp) into %s\n", spp, path);
    struct render_opts o = {.method = METHOD_BDPT, .spp = spp, .seed = 777, .threads = c->fig.threads, .max_length = c->max_length};
    struct render_stats st;
    ref = render_mc(sc, &o, &st);
    if (!img_write_exr(ref, 1.0, path, err, sizeof err)) fprintf(stderr, "%s\n", err);
    return ref;
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
    snprintf(title, sizeof title, "fig5.6: relMSE against BDPT, MMLT vs controlled small steps, p_large %g, Gaussian sigma 1/64",
             c.p_large);
    fig5_meta_head(f, &c, title);
    csv_meta(f, "reference_spp", "%d", spp);
    fig5_meta_runs(f, &c);
    fprintf(f, "kind,relmse,stderr,seeds,accept_small,mutations_per_second\n");
    for (int kind = 0; kind < 2; kind++) {
        double s = 0, s2 = 0, acc = 0, rate = 0;
        for (int i = 0; i < c.seeds; i++) {
            struct mlt_result r;
            fig5_run(sc, &c, kind ? SMALL_STEP_CONTROLLED : SMALL_STEP_PSS, c.fig.seed + (uint64_t)i, false, &r);
            double e = img_relmse(r.img, ref, 0.01);
            s += e;
            s2 += e * e;
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
        double m = s / c.seeds, se = sqrt(fmax(0, s2 / c.seeds - m * m) / (c.seeds - 1));
        fprintf(f, "%s,%.9g,%.9g,%d,%.6f,%.0f\n", fig5_kind_name[kind], m, se, c.seeds, acc, rate);
    }
    fclose(f);
    fig5_write_text(&c, "fig5.6.csv", buf);
    free(buf);
    img_destroy(ref);
    scene_free(sc);
    return 0;
}
