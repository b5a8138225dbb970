/* The normalisation b_k: the large steps' estimate agrees with the seed pass's, and the progressive
 * normalisation (mlt_opts.progressive_norm, mcmc/progressive_norm.c) rescales the image exactly.
 * Its agreement with BDPT is in test_mlt.c's Cornell-box suite. */
#include <criterion/criterion.h>

#include "camera/camera.h"
#include "mc/render.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include "support/agree.h"
#include "support/scenes.h"
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>

static struct mlt_opts cornell_opts(const struct scene *sc, enum mlt_method m)
{
    struct mlt_opts o = {.method = m,
                         .p_large = 0.1,
                         .mutations = 32L * 32 * 32,
                         .seed_paths = 2000,
                         .threads = 2,
                         .max_length = 5,
                         .seed = 11,
                         .pitp_rate = 1}; /* PITP as the thesis's: a zero-initialised rate is 0 */
    pss_opts_default(&o.pss, sc->cam.width, sc->cam.height);
    return o;
}

/* Exactly: the same seed gives the same chain with and without the progressive normalisation (the
 * large steps' targets are recorded, nothing is drawn), so with one length alive the image is the
 * seed-pass one times b(pooled) / b(seed), pixel by pixel, to rounding. PSSMLT (one chain over the
 * lengths), MMLT and PITP (paths of 3 segments only: one live chain). */
Test(normalisation, progressive_rescales_the_image_exactly)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 32, 32);
    const enum mlt_method ms[] = {MLT_PSSMLT, MLT_MMLT, MLT_PITP};
    for (int i = 0; i < 3; i++) {
        struct mlt_opts o = cornell_opts(sc, ms[i]);
        if (ms[i] != MLT_PSSMLT) o.min_length = o.max_length = 3;
        struct mlt_result a, b;
        mlt_render_ok(sc, &o, &a);
        o.progressive_norm = true;
        mlt_render_ok(sc, &o, &b);
        cr_assert_eq(a.mutations, b.mutations);
        cr_assert(b.b_image != a.b_image, "method %d: the pooled estimate equals the seed pass's", i);
        double ratio = b.b_image / a.b_image, worst = 0;
        size_t n = (size_t)3 * a.img->w * a.img->h;
        for (size_t p = 0; p < n; p++) {
            double want = ratio * a.img->px[p];
            if (want != 0)
                worst = fmax(worst, fabs(b.img->px[p] / want - 1));
            else
                cr_assert_eq(b.img->px[p], 0);
        }
        fprintf(stderr, "progressive, method %d: b %.6g -> %.6g (x %.6f), worst pixel deviation %.2g\n", i, a.b_image,
                b.b_image, ratio, worst);
        cr_assert_lt(worst, 1e-12, "method %d: the image is not the seed-pass one rescaled (worst %.3g)", i, worst);
        mlt_result_free(&a);
        mlt_result_free(&b);
    }
    scene_free(sc);
}

/* The large steps' targets are independent samples of b_k, as the seed pass's are: per length of an
 * MMLT run (Cornell box, 32x32, 20 000 seed paths, 64 mutations per pixel: ~6 500 large steps) the
 * two estimates differ by z = |b_large - b_seed| / (combined standard error) below the two-sided
 * normal quantile at alpha 0.01, Sidak over the lengths with light. */
Test(normalisation, large_steps_estimate_what_the_seed_pass_does)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 32, 32);
    struct mlt_opts o = cornell_opts(sc, MLT_MMLT);
    o.seed_paths = 20000;
    o.mutations = 64L * 32 * 32;
    struct mlt_result r;
    mlt_render_ok(sc, &o, &r);
    int live = 0;
    for (int k = 1; k <= o.max_length; k++)
        live += r.b_k[k] > 0;
    double zmax = gsl_cdf_ugaussian_Qinv((1 - pow(0.99, 1.0 / live)) / 2);
    for (int k = 1; k <= o.max_length; k++) {
        if (!(r.b_k[k] > 0)) continue;
        double se = hypot(r.b_k[k] * r.b_k_rse[k], r.bl_k[k] * r.bl_k_rse[k]);
        double z = fabs(r.bl_k[k] - r.b_k[k]) / se;
        fprintf(stderr, "length %d: seed %.6g (rse %.3g), large steps %.6g (rse %.3g, %ld samples), z %.2f\n", k,
                r.b_k[k], r.b_k_rse[k], r.bl_k[k], r.bl_k_rse[k], r.large_n[k], z);
        cr_assert(r.large_n[k] > 0, "length %d: no large steps recorded", k);
        cr_assert_lt(z, zmax, "length %d: the large steps estimate %.6g, the seed pass %.6g (z %.2f > %.2f)", k,
                     r.bl_k[k], r.b_k[k], z, zmax);
    }
    mlt_result_free(&r);
    scene_free(sc);
}

/* The MMLT paper's case for the progressive estimate: a seed pass too small to see every length (2
 * seed paths: several b_k come out 0, and the lengths seen are off by tens of per cent). Six runs
 * each at 64 mutations per pixel (Cornell box, 32x32), the squared relative error of the image's
 * mean luminance against a 256-spp BDPT render's: the progressive runs' mean must be below the seed
 * pass runs' by an F-test, one-sided at alpha 0.01 (F(6, 6)). */
Test(normalisation, progressive_finds_the_lengths_a_small_seed_pass_missed)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 32, 32);
    struct render_opts ro = {.method = METHOD_BDPT, .spp = 256, .seed = 1, .threads = 2, .max_length = 5};
    struct render_stats rs;
    struct image *ref = render_mc(sc, &ro, &rs);
    double want = img_mean_luminance(ref), sq[2] = {0, 0};
    img_destroy(ref);
    const int runs = 6;
    for (int p = 0; p < 2; p++)
        for (int i = 0; i < runs; i++) {
            struct mlt_opts o = cornell_opts(sc, MLT_MMLT);
            o.seed_paths = 2;
            o.mutations = 64L * 32 * 32;
            o.seed = 100 + (uint64_t)i;
            o.progressive_norm = p;
            struct mlt_result r;
            mlt_render_ok(sc, &o, &r);
            double e = img_mean_luminance(r.img) / want - 1;
            fprintf(stderr, "%s seed %d: image mean %+.1f %%\n", p ? "progressive" : "seed pass  ", i, 100 * e);
            sq[p] += e * e;
            mlt_result_free(&r);
        }
    double F = sq[0] / sq[1], Fcrit = gsl_cdf_fdist_Qinv(0.01, runs, runs);
    fprintf(stderr, "mean squared error: seed pass %.3g, progressive %.3g (F %.1f, critical %.2f)\n", sq[0] / runs,
            sq[1] / runs, F, Fcrit);
    cr_assert_gt(F, Fcrit, "the progressive estimate does not beat a 2-path seed pass (F %.2f <= %.2f)", F, Fcrit);
    scene_free(sc);
}
