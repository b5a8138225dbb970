/* BDPT's per-technique images (mc/bdpt_tech.h): they split the image exactly, and the variance
 * they report per pixel is the variance of the pixel's estimate across seeds. */
#include <criterion/criterion.h>

#include "camera/camera.h"
#include "mc/render.h"
#include "path/scene_ready.h"
#include "scene/scene.h"
#include "support/scenes.h"
#include <gsl/gsl_cdf.h>

static struct image *run(const struct scene *sc, int spp, uint64_t seed, int K, int tech_k, struct render_stats *st)
{
    struct render_opts o = {
        .method = METHOD_BDPT, .spp = spp, .seed = seed, .threads = 2, .max_length = K, .tech_k = tech_k};
    struct image *im = render_mc(sc, &o, st);
    cr_assert_eq(st->nonfinite, 0);
    cr_assert_not_null(st->tech);
    return im;
}

/* sums (sq: of squares) of technique t, channel ch of pixel p, in the documented layout */
static double at(const struct bdpt_tech *a, int t, bool sq, size_t p, int ch)
{
    size_t plane = 3 * (size_t)a->w * a->h;
    return a->sum[((size_t)(sq ? a->k + 1 : 0) + (size_t)(t - 1)) * plane + 3 * p + (size_t)ch];
}

/* Every technique of every length, summed, is the image (the same numbers: up to rounding). */
Test(render, bdpt_technique_images_sum_to_the_image)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 24, 24);
    const int K = 5, spp = 4;
    size_t np = 24 * 24;
    double *acc = calloc(3 * np, sizeof *acc);
    struct render_stats st;
    struct image *im = NULL;
    for (int k = 1; k <= K; k++) {
        if (im) img_destroy(im);
        im = run(sc, spp, 7, K, k, &st);
        for (int t = 1; t <= k + 1; t++)
            for (size_t p = 0; p < np; p++)
                for (int ch = 0; ch < 3; ch++)
                    acc[3 * p + ch] += at(st.tech, t, false, p, ch) / spp;
        bdpt_tech_free(st.tech);
    }
    double worst = 0;
    for (size_t i = 0; i < 3 * np; i++)
        worst = fmax(worst, fabs(acc[i] - im->px[i]) / fmax(fabs(im->px[i]), 1e-6));
    cr_assert(worst < 1e-9, "the techniques' images differ from the image by up to %g (relative)", worst);
    img_destroy(im);
    free(acc);
    scene_free(sc);
}

/* For each technique of length 2 in the furnace (light tracing, light sampling, emission hit; box
 * filter, where the reported variance is exact) the mean over pixels of (variance across S = 16
 * seeds) - (variance the run reported, averaged over the seeds) is zero: z test over the 24 x 24
 * pixels (green channel), two-sided alpha = 0.001 per technique. The furnace's contributions are
 * bounded, so the z statistic is close to normal (on the Cornell box the light's rare hits make it
 * skewed: |z| ~ 3.5 with correct variances). 4 spp keeps the small-n correction visible: reporting
 * (q/n - m^2)/n instead of the unbiased variance fails (light sampling: z = 16 measured). */
Test(stat_render, bdpt_technique_variance_is_the_spread_across_seeds)
{
    struct scene *sc = test_scene("scenes/furnace/scene.json");
    sc->cam.filter = FILTER_BOX;
    camera_resize(&sc->cam, 24, 24);
    enum { S = 16, SPP = 4, K = 3, KT = 2 };
    const size_t np = 24 * 24;
    double *m = calloc(np * (KT + 1), sizeof *m), *m2 = calloc(np * (KT + 1), sizeof *m2),
           *pred = calloc(np * (KT + 1), sizeof *pred);
    struct render_stats st;
    for (int sd = 0; sd < S; sd++) {
        img_destroy(run(sc, SPP, 100 + (uint64_t)sd, K, KT, &st));
        for (int t = 1; t <= KT + 1; t++) {
            double N = t == 1 ? (double)SPP * np : SPP;
            for (size_t p = 0; p < np; p++) {
                double v = at(st.tech, t, false, p, 1) / SPP;
                m[(t - 1) * np + p] += v;
                m2[(t - 1) * np + p] += v * v;
                pred[(t - 1) * np + p] +=
                    bdpt_tech_var(at(st.tech, t, false, p, 1), at(st.tech, t, true, p, 1), SPP, N) / S;
            }
        }
        bdpt_tech_free(st.tech);
    }
    double zc = gsl_cdf_ugaussian_Qinv(0.0005);
    for (int t = 1; t <= KT + 1; t++) {
        double sd_ = 0, sdd = 0, mean_pred = 0;
        for (size_t p = 0; p < np; p++) {
            size_t i = (t - 1) * np + p;
            double emp = (m2[i] - m[i] * m[i] / S) / (S - 1), d = emp - pred[i];
            sd_ += d;
            sdd += d * d;
            mean_pred += pred[i] / np;
        }
        double mean = sd_ / np, se = sqrt((sdd / np - mean * mean) / (np - 1)), z = mean / se;
        cr_log_info("t = %d: mean reported variance %.4g, mean difference %.3g, z = %.2f", t, mean_pred, mean, z);
        cr_assert(mean_pred > 0, "t = %d: no variance reported", t);
        cr_assert(fabs(z) < zc, "t = %d: reported variance %.4g vs spread across seeds: z = %.2f (|z| < %.2f)", t,
                  mean_pred, z, zc);
    }
    free(m);
    free(m2);
    free(pred);
    scene_free(sc);
}
