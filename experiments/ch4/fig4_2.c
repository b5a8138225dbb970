/* bin/fig4_2: thesis Figure 4.2. PSSMLT small steps on the diffuse wall (scenes/wall) at square
 * resolutions 1024, 512 and 256, and resolution-aware proposals scaled to the resolution
 * (--rap-resolution: a fixed step size in pixels, that of 1024) at 256; equal mutations per pixel.
 * Over several seeds: the error's correlation lengths in pixels (as in fig4_1: lag where the
 * autocorrelation normalised at lag 1 falls below 1/e), relMSE against a PT reference per
 * resolution, small-step acceptance.
 * Writes OUT/fig4.2.csv (config,resolution,quantity,seeds,mean,se), OUT/fig4.2-runs.csv and the
 * first seed's images {pssmlt-1024,pssmlt-512,pssmlt-256,rap-resolution-256}.{exr,png}. */
#include "base/parallel.h"
#include "base/util.h"
#include "camera/camera.h"
#include "ch4/ch4_common.h"
#include "ch4/wall_noise.h"
#include "common/csv_meta.h"
#include "common/opts.h"
#include "path/scene_ready.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NCONF 4

enum { Q_LX, Q_LY, Q_L, Q_RHO1, Q_RELMSE, Q_ACCEPT, NQ };
static const char *qn[NQ] = {"l_x", "l_y", "l", "rho1", "relmse", "small_accept"};

int main(int argc, char **argv)
{
    const char *prog = "fig4_2";
    struct opts_figure fo;
    int seeds, refspp, maxlag;
    double mpp, p_large;
    const struct opt opts[] = {
        OPTS_FIGURE(fo, "scenes/wall/scene.json", "results/fig4.2"),
        OPT_MPP(mpp, .lo = 0.01, .hi = 1e6, .help = "PSSMLT mutations per pixel", .def = "4", .paper = "64"),
        OPT_SEEDS(seeds, .help = "runs per configuration, seeds S..S+N-1", .def = "4", .paper = "8"),
        OPT_P_LARGE(p_large),
        {"--max-lag", OPT_INT, OPT_DST(maxlag), .arg = "L", .lo = 2, .hi = 255, .help = "autocorrelation lags 0..L pixels",
         .def = "64"},
        OPT_REFERENCE_SPP(refspp, .help = "PT samples per pixel of the references, cached as "
                                          "results/reference/wall-pt-NxN-SPP.exr", .def = "32", .paper = "1024"),
        {0}};
    opts_parse(&(struct opts_spec){.prog = prog, .usage = "usage: fig4_2 [options]\n", .opts = opts, .paper = &fo.paper},
               argc, argv);
    opts_require_image_output(prog);
    char err[1024];
    struct scene *sc = scene_load(fo.scene, err, sizeof err);
    if (!sc) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    if (!ch4_mkdir(fo.out, err, sizeof err)) {
        fprintf(stderr, "%s: %s\n", prog, err);
        return 1;
    }
    const char *names[NCONF] = {"pssmlt-1024", "pssmlt-512", "pssmlt-256", "rap-resolution-256"};
    const int res[NCONF] = {1024, 512, 256, 256};
    struct wall_cfg cfg = {
        .p_large = p_large, .mpp = mpp, .seed_paths = fo.paper ? 1000000 : 100000, .threads = fo.threads, .maxlag = maxlag};
    double *q[NQ];
    for (int i = 0; i < NQ; i++)
        q[i] = xcalloc((size_t)NCONF * seeds, sizeof(double));
    double refvar[NCONF], errvar[NCONF] = {0};
    struct image *ref = NULL;
    for (int c = 0; c < NCONF; c++) {
        camera_resize(&sc->cam, res[c], res[c]);
        if (!ref || ref->w != res[c]) {
            char refpath[256];
            snprintf(refpath, sizeof refpath, "results/reference/wall-pt-%dx%d-%d.exr", res[c], res[c], refspp);
            img_destroy(ref);
            ref = ch4_reference(sc, METHOD_PT, refspp, refpath, fo.threads, prog, err, sizeof err);
            if (!ref) {
                fprintf(stderr, "%s: %s\n", prog, err);
                return 1;
            }
        }
        refvar[c] = ch4_pixel_noise_var(ref);
        cfg.rap = cfg.rap_resolution = c == 3;
        for (int s = 0; s < seeds; s++) {
            fprintf(stderr, "%s: %s, seed %llu (%d of %d)\n", prog, names[c], (unsigned long long)(fo.seed + s), s + 1,
                    seeds);
            struct wall_meas m;
            struct image *img = wall_run(sc, &cfg, fo.seed + s, ref, &m, err, sizeof err);
            if (!img) {
                fprintf(stderr, "%s: %s\n", prog, err);
                return 1;
            }
            int k = c * seeds + s;
            q[Q_LX][k] = m.lx, q[Q_LY][k] = m.ly, q[Q_L][k] = 0.5 * (m.lx + m.ly);
            q[Q_RHO1][k] = 0.5 * (m.rho1_x + m.rho1_y), q[Q_RELMSE][k] = m.relmse, q[Q_ACCEPT][k] = m.accept;
            errvar[c] += m.err_var / seeds;
            if (s == 0 && !ch4_write_pair(img, fo.out, names[c], err, sizeof err)) {
                fprintf(stderr, "%s: %s\n", prog, err);
                return 1;
            }
            wall_meas_free(&m);
            img_destroy(img);
        }
    }
    img_destroy(ref);
    char *rb = NULL, *sb = NULL;
    size_t rl = 0, sl = 0;
    FILE *fr = open_memstream(&rb, &rl), *fs = open_memstream(&sb, &sl);
    FILE *all[2] = {fr, fs};
    for (int i = 0; i < 2; i++) {
        csv_meta_head(all[i], "fig4.2: PSSMLT small steps on a square diffuse wall at 1024, 512, 256 and with"
                              " --rap-resolution (reference 1024 px) at 256", fo.scene, fo.scale);
        csv_meta(all[i], "mutations_per_pixel", "%g", mpp);
        csv_meta(all[i], "p_large", "%g", p_large);
        csv_meta(all[i], "kernel", "kelemen s1 1/1024 s2 1/64");
        ch4_meta_runs(all[i], fo.seed, seeds, fo.threads);
        csv_meta(all[i], "reference", "PT %d spp", refspp);
        for (int c = 0; c < NCONF; c++)
            csv_meta(all[i], NULL, "%s: reference pixel-noise variance %.4g, error variance %.4g", names[c], refvar[c],
                     errvar[c]);
        csv_meta(all[i], NULL, "l_x, l_y = lag (pixels) where the error's autocorrelation normalised at lag 1 falls below 1/e;"
                               " l = their mean; rho1 = mean lag-1 autocorrelation");
    }
    fprintf(fr, "config,resolution,seed");
    for (int i = 0; i < NQ; i++)
        fprintf(fr, ",%s", qn[i]);
    fprintf(fr, "\n");
    fprintf(fs, "config,resolution,quantity,seeds,mean,se\n");
    for (int c = 0; c < NCONF; c++) {
        for (int s = 0; s < seeds; s++) {
            fprintf(fr, "%s,%d,%llu", names[c], res[c], (unsigned long long)(fo.seed + s));
            for (int i = 0; i < NQ; i++)
                fprintf(fr, ",%.6g", q[i][c * seeds + s]);
            fprintf(fr, "\n");
        }
        for (int i = 0; i < NQ; i++) {
            double mean, se;
            ch4_mean_se(q[i] + c * seeds, seeds, &mean, &se);
            fprintf(fs, "%s,%d,%s,%d,%.6g,%.6g\n", names[c], res[c], qn[i], seeds, mean, se);
        }
    }
    fclose(fr), fclose(fs);
    char p1[4096], p2[4096];
    snprintf(p1, sizeof p1, "%s/fig4.2-runs.csv", fo.out);
    snprintf(p2, sizeof p2, "%s/fig4.2.csv", fo.out);
    bool ok = write_text_atomic(p1, rb, err, sizeof err) && write_text_atomic(p2, sb, err, sizeof err);
    free(rb), free(sb);
    for (int i = 0; i < NQ; i++)
        free(q[i]);
    scene_free(sc);
    if (!ok) {
        fprintf(stderr, "%s: %s\n", prog, err);
        return 1;
    }
    fprintf(stderr, "%s: wrote %s, %s\n", prog, p2, p1);
    return 0;
}
