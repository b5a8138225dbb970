/* Per-technique images (core/stats/tech_image.h): the contributions split by technique add up to the
 * length-k image, the sample counts add up to the iterations spent on length k, and the "follow"
 * statistics on accumulators built by hand. */
#include <criterion/criterion.h>

#include "camera/camera.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include "support/scenes.h"
#include <math.h>
#include <string.h>

static void opts(struct mlt_opts *o, const struct scene *sc, enum mlt_method m, int k, int min_len)
{
    *o = (struct mlt_opts){.method = m,
                           .p_large = 0.1,
                           .pitp_rate = 1,
                           .mutations = 60000,
                           .seed_paths = 5000,
                           .threads = 2,
                           .max_length = 6,
                           .min_length = min_len,
                           .seed = 3,
                           .technique_k = k};
    pss_opts_default(&o->pss, sc->cam.width, sc->cam.height);
}

static double count_sum(const struct tech_acc *a, int t)
{
    double n = 0;
    for (size_t p = 0; p < (size_t)a->w * a->h; p++)
        n += a->count[t][p];
    return n;
}

/* With paths of length k only, the image is the length-k part: the techniques' images must sum to
 * it pixel by pixel (up to the order of the additions). */
static void check_sum_is_image(enum mlt_method m)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 24, 24);
    struct mlt_opts o;
    opts(&o, sc, m, 3, 3);
    o.max_length = 3;
    struct mlt_result r;
    char err[256];
    cr_assert(mlt_render(sc, &o, &r, err, sizeof err), "%s", err);
    cr_assert_not_null(r.tech);
    double total = 0, worst = 0, nonzero_t = 0;
    for (int y = 0; y < 24; y++)
        for (int x = 0; x < 24; x++) {
            rgb s = v3s(0), im = img_get(r.img, x, y);
            for (int t = 1; t <= 4; t++)
                s = vadd(s, img_get(r.tech->contrib[t], x, y));
            total += luminance(im);
            worst = fmax(worst, fabs(luminance(s) - luminance(im)));
        }
    for (int t = 1; t <= 4; t++)
        nonzero_t += count_sum(r.tech, t) > 0;
    cr_assert_gt(total, 0);
    cr_assert_lt(worst, 1e-9 * total, "%s: largest pixel difference %g (image sum %g)",
                 m == MLT_MMLT ? "mmlt" : "pssmlt", worst, total);
    cr_assert_geq(nonzero_t, 3, "the Cornell box's length-3 paths come from several techniques");
    /* every iteration is on length 3: one chain sample each */
    cr_assert_eq(r.tech->samples, r.mutations);
    double n = 0;
    for (int t = 1; t <= 4; t++) {
        n += count_sum(r.tech, t);
        cr_assert_leq(count_sum(r.tech, t), (double)r.mutations);
    }
    if (m == MLT_MMLT)
        cr_assert_eq(n, (double)r.mutations, "an MMLT state is in one technique: %g samples of %ld", n, r.mutations);
    else
        cr_assert_gt(n, (double)r.mutations, "a PSSMLT state is in every technique it connects: %g of %ld", n,
                     r.mutations);
    mlt_result_free(&r);
    scene_free(sc);
}

Test(tech_image, mmlt_techniques_sum_to_the_image) { check_sum_is_image(MLT_MMLT); }
Test(tech_image, pssmlt_techniques_sum_to_the_image) { check_sum_is_image(MLT_PSSMLT); }

/* All lengths rendered: MMLT's counts of length 3 are the iterations of its length-3 chain. */
Test(tech_image, mmlt_counts_are_the_length_k_mutations)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 24, 24);
    struct mlt_opts o;
    opts(&o, sc, MLT_MMLT, 3, 1);
    struct mlt_result r;
    char err[256];
    cr_assert(mlt_render(sc, &o, &r, err, sizeof err), "%s", err);
    long spent = r.stats.any[PROPOSAL_SMALL][3].attempts + r.stats.any[PROPOSAL_LARGE][3].attempts;
    cr_assert_gt(spent, 0);
    cr_assert_lt(spent, r.mutations);
    cr_assert_eq(r.tech->samples, spent);
    double n = 0;
    for (int t = 1; t <= 4; t++)
        n += count_sum(r.tech, t);
    cr_assert_eq(n, (double)spent);
    mlt_result_free(&r);
    scene_free(sc);
}

Test(tech_image, refuses_pitp_mctls_and_lengths_out_of_range)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 8, 8);
    struct mlt_opts o;
    struct mlt_result r;
    char err[256];
    opts(&o, sc, MLT_PITP, 3, 1);
    cr_assert_not(mlt_render(sc, &o, &r, err, sizeof err));
    opts(&o, sc, MLT_MMLT, 3, 1);
    o.large_step = LARGE_MCTLS;
    cr_assert_not(mlt_render(sc, &o, &r, err, sizeof err));
    opts(&o, sc, MLT_MMLT, 7, 1);
    cr_assert_not(mlt_render(sc, &o, &r, err, sizeof err));
    opts(&o, sc, MLT_PSSMLT, 2, 3);
    cr_assert_not(mlt_render(sc, &o, &r, err, sizeof err));
    cr_assert(strstr(err, "technique images"), "%s", err);
    scene_free(sc);
}

/* tech_follow on two techniques over 16x8 pixels (two 8x8 blocks): counts proportional to the
 * contributions give tv = 0 and r = 1; equal counts against unequal contributions give the
 * half-L1 distance of the shares. */
Test(tech_image, follow_statistics)
{
    struct tech_acc a;
    tech_acc_init(&a, 1, 16, 8, false);
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 16; x++) {
            double c1 = x < 8 ? 3 : 1, c2 = x < 8 ? 1 : 1;
            img_add(a.contrib[1], x, y, v3s(c1));
            img_add(a.contrib[2], x, y, v3s(c2));
            a.count[1][y * 16 + x] = 2 * c1;
            a.count[2][y * 16 + x] = 2 * c2;
        }
    struct tech_follow f;
    tech_follow(&a, 8, &f);
    cr_assert_float_eq(f.tv, 0, 1e-12);
    cr_assert_float_eq(f.r, 1, 1e-12);
    cr_assert_eq(f.cells, 4);
    cr_assert_float_eq(f.contrib_share[1], 4.0 / 6.0, 1e-12);
    for (size_t p = 0; p < 128; p++)
        a.count[1][p] = a.count[2][p] = 5;
    tech_follow(&a, 8, &f);
    cr_assert_float_eq(f.sample_share[1], 0.5, 1e-12);
    cr_assert_float_eq(f.tv, 4.0 / 6.0 - 0.5, 1e-12);
    cr_assert(isnan(f.r), "constant sample shares have no correlation, got %g", f.r);
    tech_acc_free(&a);
}
