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
#include "common/opts.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define NMETH 3

static bool write_stats(const struct mlt_stats *st, const char *method, const char *dir, char *err, size_t n)
{
    char *buf = NULL, path[4096];
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    stats_write_csv(f, method, st, true);
    fclose(f);
    snprintf(path, sizeof path, "%s/%s-stats.csv", dir, method);
    bool ok = write_text_atomic(path, buf, err, n);
    free(buf);
    return ok;
}

/* Thesis §4.2 on Figure 4.3, at equal samples per pixel. */
static char *claims(const char *const *names, const double *rel, const double *acc, int seeds, const char *out,
                    const char *scale, char *err, size_t errlen)
{
    struct claims cl;
    char command[64];
    snprintf(command, sizeof command, "make fig4.3 SCALE=%s", scale);
    claims_begin(&cl, scale, command, "Claims of thesis §4.2 on Fig. 4.3, %d seeds", seeds);
    const bool mcmc[NMETH] = {false, true, true}, all[NMETH] = {true, true, true};
    const char *src = "thesis §4.2, Fig. 4.3";
    ch4_claim_extreme(&cl, src, "fixing discrete choices raises PSSMLT's small-step acceptance",
                      "small-step acceptance", names, acc, NMETH, mcmc, 2, +1, seeds);
    ch4_claim_extreme(&cl, src, "fixing discrete choices lowers PSSMLT's error", "relMSE", names, rel, NMETH, mcmc, 2,
                      -1, seeds);
    ch4_claim_extreme(&cl, src, "BDPT has difficulty rendering this scene", "relMSE", names, rel, NMETH, all, 0, +1,
                      seeds);
    return claims_finish(&cl, out, err, errlen);
}

int main(int argc, char **argv)
{
    const char *prog = "fig4_3", *refpath = NULL;
    struct opts_figure fo;
    int res[2] = {-1, -1}, spp, seeds, refspp;
    double p_large;
    const struct opt opts[] = {
        OPTS_FIGURE(fo, "scenes/window/scene.json", "results/fig4.3"),
        OPT_RESOLUTION(res, .lo = 1, .hi = 1 << 14, .help = "image size; quick: the scene's", .paper = "256x144"),
        {"--spp", OPT_INT, OPT_DST(spp), .arg = "N", .lo = 1, .hi = 1 << 20,
         .help = "samples (mutations) per pixel of every method", .def = "64"},
        OPT_SEEDS(seeds, .help = "runs per method, seeds S..S+N-1", .def = "24", .paper = "16"),
        OPT_P_LARGE(p_large),
        OPTS_REFERENCE(refpath, refspp, "BDPT", "results/reference/window-bdpt-WxH-SPP.exr", "1024", "16384"),
        {0}};
    opts_parse(&(struct opts_spec){.prog = prog, .usage = "usage: fig4_3 [options]\n", .opts = opts, .fig = &fo},
               argc, argv);
    int W = res[0], H = res[1];
    opts_require_image_output(prog);
    char err[1024];
    struct scene *sc = scene_load(fo.scene, err, sizeof err);
    if (!sc) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    if (W > 0) camera_resize(&sc->cam, W, H);
    W = sc->cam.width, H = sc->cam.height;
    char defref[256];
    snprintf(defref, sizeof defref, "results/reference/window-bdpt-%dx%d-%d.exr", W, H, refspp);
    if (!refpath) refpath = defref;
    if (!ch4_mkdir(fo.out, err, sizeof err)) {
        fprintf(stderr, "%s: %s\n", prog, err);
        return 1;
    }
    struct image *ref = ch4_reference(sc, METHOD_BDPT, refspp, refpath, fo.threads, prog, err, sizeof err);
    if (!ref || !ch4_write_pair(ref, fo.out, "reference", err, sizeof err)) {
        fprintf(stderr, "%s: %s\n", prog, err);
        return 1;
    }
    const char *names[NMETH] = {"bdpt", "pssmlt", "pssmlt-cdc"};
    double *rel = xcalloc((size_t)NMETH * seeds, sizeof *rel), *acc = xcalloc((size_t)NMETH * seeds, sizeof *acc);
    double *sec = xcalloc((size_t)NMETH * seeds, sizeof *sec);
    for (int m = 0; m < NMETH; m++)
        for (int s = 0; s < seeds; s++) {
            int k = m * seeds + s;
            fprintf(stderr, "%s: %s, seed %llu (%d of %d)\n", prog, names[m], (unsigned long long)(fo.seed + s), s + 1,
                    seeds);
            struct image *img;
            acc[k] = NAN;
            if (m == 0) {
                struct render_opts o = {.method = METHOD_BDPT,
                                        .spp = spp,
                                        .seed = fo.seed + s,
                                        .threads = fo.threads,
                                        .max_length = sc->max_length,
                                        .progress = isatty(2)};
                struct render_stats st;
                img = render_mc(sc, &o, &st);
                sec[k] = st.seconds;
            } else {
                struct mlt_opts o = {.method = MLT_PSSMLT,
                                     .p_large = p_large,
                                     .mutations = (long)spp * W * H,
                                     .seed_paths = fo.paper ? 1000000 : 100000,
                                     .seed = fo.seed + s,
                                     .threads = fo.threads,
                                     .max_length = sc->max_length,
                                     .progress = isatty(2)};
                pss_opts_default(&o.pss, W, H);
                o.pss.cdc = m == 2;
                struct mlt_result r;
                if (!mlt_render(sc, &o, &r, err, sizeof err)) {
                    fprintf(stderr, "%s: %s\n", prog, err);
                    return 1;
                }
                acc[k] = cell_mean(&r.stats.total[PROPOSAL_SMALL]);
                sec[k] = r.seconds + r.seed_seconds;
                if (s == 0 && !write_stats(&r.stats, names[m], fo.out, err, sizeof err)) {
                    fprintf(stderr, "%s: %s\n", prog, err);
                    return 1;
                }
                img = r.img;
                r.img = NULL;
                mlt_result_free(&r);
            }
            rel[k] = img_relmse(img, ref, 0.01);
            if (s == 0 && !ch4_write_pair(img, fo.out, names[m], err, sizeof err)) {
                fprintf(stderr, "%s: %s\n", prog, err);
                return 1;
            }
            img_destroy(img);
        }
    char *rb = NULL, *sb = NULL;
    size_t rl = 0, sl = 0;
    FILE *fr = open_memstream(&rb, &rl), *fs = open_memstream(&sb, &sl);
    FILE *all[2] = {fr, fs};
    for (int i = 0; i < 2; i++) {
        csv_meta_head(all[i], "fig4.3: BDPT vs PSSMLT vs PSSMLT with constrained discrete choices (--cdc), equal samples per pixel",
                      fo.scene, fo.scale);
        csv_meta(all[i], "resolution", "%dx%d", W, H);
        csv_meta(all[i], "spp", "%d", spp);
        csv_meta(all[i], "p_large", "%g", p_large);
        ch4_meta_runs(all[i], fo.seed, seeds, fo.threads);
        csv_meta(all[i], "reference", "%s (BDPT %d spp)", refpath, refspp);
        csv_meta(all[i], NULL, "relmse = mean over pixels and channels of (I - R)^2 / (R^2 + 0.01); small_accept = mean "
                               "min(1, a) of small steps");
    }
    fprintf(fr, "method,seed,relmse,small_accept,seconds\n");
    fprintf(fs, "method,quantity,seeds,mean,se\n");
    for (int m = 0; m < NMETH; m++) {
        for (int s = 0; s < seeds; s++) {
            int k = m * seeds + s;
            fprintf(fr, "%s,%llu,%.6g,%.6g,%.3f\n", names[m], (unsigned long long)(fo.seed + s), rel[k], acc[k], sec[k]);
        }
        double mean, se;
        ch4_mean_se(rel + m * seeds, seeds, &mean, &se);
        fprintf(fs, "%s,relmse,%d,%.6g,%.6g\n", names[m], seeds, mean, se);
        if (m > 0) {
            ch4_mean_se(acc + m * seeds, seeds, &mean, &se);
            fprintf(fs, "%s,small_accept,%d,%.6g,%.6g\n", names[m], seeds, mean, se);
        }
        if (m == 0) {
            /* relMSE(BDPT, R) = V (1/spp + 1/refspp) for BDPT's per-sample variance term V: the
             * reference's own share V / refspp is part of every method's relMSE */
            ch4_mean_se(rel, seeds, &mean, &se);
            fprintf(fs, "reference,relmse_own,%d,%.6g,%.6g\n", seeds, mean * spp / (spp + refspp),
                    se * spp / (spp + refspp));
        }
    }
    fclose(fr), fclose(fs);
    char p1[4096], p2[4096];
    snprintf(p1, sizeof p1, "%s/fig4.3-runs.csv", fo.out);
    snprintf(p2, sizeof p2, "%s/fig4.3.csv", fo.out);
    bool ok = write_text_atomic(p1, rb, err, sizeof err) && write_text_atomic(p2, sb, err, sizeof err);
    char *md = ok ? claims(names, rel, acc, seeds, fo.out, fo.scale, err, sizeof err) : NULL;
    ok = ok && md;
    if (md) fputs(md, stderr);
    free(md);
    free(rb), free(sb), free(rel), free(acc), free(sec);
    img_destroy(ref);
    scene_free(sc);
    if (!ok) {
        fprintf(stderr, "%s: %s\n", prog, err);
        return 1;
    }
    fprintf(stderr, "%s: wrote %s, %s\n", prog, p2, p1);
    return 0;
}
