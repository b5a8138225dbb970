/* bin/fig4_2: thesis Figure 4.2. PSSMLT small steps on the diffuse wall (scenes/wall) at square
 * resolutions 1024, 512 and 256, and resolution-aware proposals scaled to the resolution
 * (--rap-resolution: a fixed step size in pixels, that of 1024) at 256; equal mutations per pixel.
 * Over several seeds: the error's correlation lengths in pixels (as in fig4_1: lag where the
 * autocorrelation normalised at lag 1 falls below 1/e), relMSE against a PT reference per
 * resolution, small-step acceptance.
 * Then the glossy-to-glossy case for which the thesis does not scale steps to the resolution
 * (scenes/wall-glossy: camera - glossy wall - glossy panel - light): small-step acceptance at 1024,
 * 512 and 256 without and (512, 256; at 1024 the scaling is 1) with --rap-resolution, at a fixed
 * number of mutations per run (acceptance needs no image statistics).
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
#include "path/scene_ready.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define NCONF 4
#define NGLOSSY 5

enum { Q_LX, Q_LY, Q_L, Q_RHO1, Q_RELMSE, Q_ACCEPT, NQ };
static const char *qn[NQ] = {"l_x", "l_y", "l", "rho1", "relmse", "small_accept"};
static const char *gnames[NGLOSSY] = {"glossy-pssmlt-1024", "glossy-pssmlt-512", "glossy-pssmlt-256",
                                      "glossy-rap-resolution-512", "glossy-rap-resolution-256"};
static const int gres[NGLOSSY] = {1024, 512, 256, 512, 256};
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
    double *q[NQ], *gacc;
    double refvar[NCONF], errvar[NCONF];
};

/* Small-step acceptance of one PSSMLT run of `mutations` on the glossy scene at the camera's size. */
static bool glossy_accept(const struct scene *sc, bool rap_resolution, long mutations, double p_large, uint64_t seed,
                          int threads, double *accept, char *err, size_t errlen)
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
    mlt_result_free(&r);
    return true;
}

/* Thesis §4.1 on Figure 4.2: the diffuse wall's noise at smaller resolutions and with resolution
 * scaling (q: the per-run quantities of the NCONF configurations), and the glossy case's
 * acceptance (gacc: NGLOSSY configurations). */
static char *claims(double *const *q, const double *gacc, int seeds, const char *out, const char *scale, char *err,
                    size_t errlen)
{
    struct claims cl;
    char command[64], zs[128], md[256];
    snprintf(command, sizeof command, "make fig4.2 SCALE=%s", scale);
    claims_begin(&cl, scale, command, "Claims of thesis §4.1 on Fig. 4.2, %d seeds", seeds);
    const bool plain[NCONF] = {true, true, true, false}, at256[NCONF] = {false, false, true, true};
    const char *src = "thesis §4.1, Fig. 4.2";
    const char *blotchy = "smaller images get blotchier noise (PSSMLT, equal mutations per pixel)";
    ch4_claim_extreme(&cl, src, blotchy, "lag-1 autocorrelation of the error", names, q[Q_RHO1], NCONF, plain, 2, +1,
                      seeds);
    ch4_claim_extreme(&cl, src, blotchy, "relMSE", names, q[Q_RELMSE], NCONF, plain, 2, +1, seeds);
    ch4_claim_extreme(&cl, src, "steps scaled to the resolution remove it at 256²",
                      "lag-1 autocorrelation of the error", names, q[Q_RHO1], NCONF, at256, 3, -1, seeds);
    double m[2], se[2];
    mean_se(q[Q_RELMSE] + 3 * seeds, seeds, &m[0], &se[0]);
    mean_se(q[Q_RELMSE], seeds, &m[1], &se[1]);
    struct verdict v = verdict_similar(m[0], se[0], m[1], se[1], 0.05, seeds);
    snprintf(zs, sizeof zs, "pssmlt-1024-5%%=%.2f", v.zmin);
    snprintf(md, sizeof md, "pssmlt-1024 %.4g ± %.2g within ±5 %% (z = %.1f)", m[1], se[1], v.zmin);
    claims_row(&cl, src, "steps scaled to the resolution give 256² the relMSE of 1024²", "relMSE", names[3], m[0],
               se[0], zs, md, &v);
    /* glossy: scaled steps at 256² against unscaled ones at 256² and at 1024² (where the scaling is 1) */
    const bool g[NGLOSSY] = {true, false, true, false, true};
    ch4_claim_extreme(&cl, src,
                      "glossy-to-glossy transport: steps scaled to the resolution lose acceptance as it decreases",
                      "small-step acceptance (scenes/wall-glossy)", gnames, gacc, NGLOSSY, g, 4, -1, seeds);
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
    opts_require_image_output(prog);
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
    if (!gsc) {
        fprintf(stderr, "%s\n", err);
        exit(2);
    }
    t->gacc = xcalloc((size_t)NGLOSSY * t->seeds, sizeof *t->gacc);
    bool ok = true;
    for (int c = 0; c < NGLOSSY && ok; c++) {
        camera_resize(&gsc->cam, gres[c], gres[c]);
        for (int s = 0; s < t->seeds && ok; s++) {
            fprintf(stderr, "%s: %s, seed %llu (%d of %d)\n", prog, gnames[c], (unsigned long long)(t->fo.seed + s),
                    s + 1, t->seeds);
            ok = glossy_accept(gsc, c >= 3, t->gmut, t->p_large, t->fo.seed + s, t->fo.threads,
                               &t->gacc[c * t->seeds + s], err, errlen);
        }
    }
    scene_free(gsc);
    return ok;
}

/* The rows of OUT/fig4.2-runs.csv (fr) and OUT/fig4.2.csv (fs). */
static void write_rows(const struct fig42 *t, FILE *fr, FILE *fs)
{
    int seeds = t->seeds;
    fprintf(fr, "config,resolution,seed");
    for (int i = 0; i < NQ; i++)
        fprintf(fr, ",%s", qn[i]);
    fprintf(fr, "\n");
    fprintf(fs, "config,resolution,quantity,seeds,mean,se\n");
    for (int c = 0; c < NCONF; c++) {
        for (int s = 0; s < seeds; s++) {
            fprintf(fr, "%s,%d,%llu", names[c], res[c], (unsigned long long)(t->fo.seed + s));
            for (int i = 0; i < NQ; i++)
                fprintf(fr, ",%.6g", t->q[i][c * seeds + s]);
            fprintf(fr, "\n");
        }
        for (int i = 0; i < NQ; i++) {
            double mean, se;
            mean_se(t->q[i] + c * seeds, seeds, &mean, &se);
            fprintf(fs, "%s,%d,%s,%d,%.6g,%.6g\n", names[c], res[c], qn[i], seeds, mean, se);
        }
    }
    for (int c = 0; c < NGLOSSY; c++) {
        for (int s = 0; s < seeds; s++)
            fprintf(fr, "%s,%d,%llu,,,,,,%.6g\n", gnames[c], gres[c], (unsigned long long)(t->fo.seed + s),
                    t->gacc[c * seeds + s]);
        double mean, se;
        mean_se(t->gacc + c * seeds, seeds, &mean, &se);
        fprintf(fs, "%s,%d,small_accept,%d,%.6g,%.6g\n", gnames[c], gres[c], seeds, mean, se);
    }
}

/* OUT/fig4.2-runs.csv and OUT/fig4.2.csv, with the same metadata. */
static bool write_tables(const struct fig42 *t, char *err, size_t errlen)
{
    const struct opts_figure *fo = &t->fo;
    char *rb = NULL, *sb = NULL;
    size_t rl = 0, sl = 0;
    FILE *fr = open_memstream(&rb, &rl), *fs = open_memstream(&sb, &sl);
    FILE *all[2] = {fr, fs};
    for (int i = 0; i < 2; i++) {
        csv_meta_head(all[i],
                      "fig4.2: PSSMLT small steps on a square diffuse wall at 1024, 512, 256 and with"
                      " --rap-resolution (reference 1024 px) at 256",
                      fo->scene, fo->scale);
        csv_meta(all[i], "mutations_per_pixel", "%g", t->mpp);
        csv_meta(all[i], "p_large", "%g", t->p_large);
        csv_meta(all[i], "kernel", "kelemen s1 1/1024 s2 1/64");
        ch4_meta_runs(all[i], fo->seed, t->seeds, fo->threads);
        csv_meta(all[i], "reference", "PT %d spp", t->refspp);
        for (int c = 0; c < NCONF; c++)
            csv_meta(all[i], NULL, "%s: reference pixel-noise variance %.4g, error variance %.4g", names[c],
                     t->refvar[c], t->errvar[c]);
        csv_meta(all[i], NULL,
                 "l_x, l_y = lag (pixels) where the error's autocorrelation normalised at lag 1 falls below 1/e;"
                 " l = their mean; rho1 = mean lag-1 autocorrelation");
        csv_meta(all[i], "glossy", "%s, %ld mutations per run (glossy-*: small_accept only)", t->glossy_scene, t->gmut);
    }
    write_rows(t, fr, fs);
    fclose(fr), fclose(fs);
    const char *names[2] = {"fig4.2-runs.csv", "fig4.2.csv"};
    return ch4_write_texts(prog, fo->out, 2, names, (char *[]){rb, sb}, err, errlen);
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
    ok = ok && ch4_show_claims(claims(t.q, t.gacc, t.seeds, t.fo.out, t.fo.scale, err, sizeof err));
    free(t.gacc);
    for (int i = 0; i < NQ; i++)
        free(t.q[i]);
    if (!ok) die(DIE_RUNTIME, prog, "%s", err);
    return 0;
}
