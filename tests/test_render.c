/* Estimator agreement: the furnace's exact answer, PT vs BDPT on the Cornell box, and every BDPT
 * technique alone against the others (each one is an unbiased estimator of its path length). */
#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>

#include "camera.h"
#include "render.h"
#include "scenes.h"

static struct image *run(const struct scene *sc, enum method m, int spp, uint64_t seed, int K, int s, int t)
{
    struct render_opts o = {m, spp, seed, 2, K, false, s, t};
    struct render_stats st;
    struct image *im = render_mc(sc, &o, &st);
    cr_assert_eq(st.nonfinite, 0);
    return im;
}

static double mean_lum(const struct image *im)
{
    double s = 0;
    for (int y = 0; y < im->h; y++)
        for (int x = 0; x < im->w; x++) s += luminance(img_get(im, x, y));
    return s / ((double)im->w * im->h);
}

/* The furnace (scenes/furnace): albedo a = 0.5, radiance Le = 0.5 on every inner wall, so a path of
 * length k carries a^(k-1) Le and the pixel value with lengths <= K is Le (1 - a^K) / (1 - a).
 * 64x64 pixels x 4 spp per seed; the tolerance is the issue's +-1 %. */
Test(stat_render, furnace_exact_answer)
{
    struct scene *sc = test_scene("scenes/furnace/scene.json");
    camera_resize(&sc->cam, 64, 64);
    const int K = 6;
    double exact = 0.5 * (1 - pow(0.5, K)) / (1 - 0.5);
    for (int m = 0; m < 2; m++)
        for (uint64_t seed = 1; seed <= 3; seed++) {
            struct image *im = run(sc, (enum method)m, 4, seed, K, 0, 0);
            double v = mean_lum(im);
            cr_assert(fabs(v / exact - 1) < 0.01, "%s seed %d: %g vs exact %g", method_name((enum method)m),
                      (int)seed, v, exact);
            img_destroy(im);
        }
    scene_free(sc);
}

#define REPS 8

struct stack {
    int w, h;
    double m[64 * 64], v[64 * 64], mean, mean_se;
};

/* REPS independent renders -> per-block mean and variance of the mean of luminance. */
static void stack_runs(const struct scene *sc, enum method m, int spp, int K, int s, int t, uint64_t seed0, int BLK,
                       struct stack *out)
{
    int W = sc->cam.width / BLK, H = sc->cam.height / BLK;
    double sum[64 * 64] = {0}, sum2[64 * 64] = {0}, tot[REPS];
    out->w = W;
    out->h = H;
    for (int r = 0; r < REPS; r++) {
        struct image *im = run(sc, m, spp, seed0 + r, K, s, t);
        tot[r] = mean_lum(im);
        for (int by = 0; by < H; by++)
            for (int bx = 0; bx < W; bx++) {
                double a = 0;
                for (int y = 0; y < BLK; y++)
                    for (int x = 0; x < BLK; x++) a += luminance(img_get(im, bx * BLK + x, by * BLK + y));
                a /= BLK * BLK;
                sum[by * W + bx] += a;
                sum2[by * W + bx] += a * a;
            }
        img_destroy(im);
    }
    for (int i = 0; i < W * H; i++) {
        out->m[i] = sum[i] / REPS;
        out->v[i] = fmax(0, (sum2[i] - REPS * out->m[i] * out->m[i]) / (REPS - 1)) / REPS;
    }
    double mm = 0, vv = 0;
    for (int r = 0; r < REPS; r++) mm += tot[r];
    mm /= REPS;
    for (int r = 0; r < REPS; r++) vv += sqr(tot[r] - mm);
    out->mean = mm;
    out->mean_se = sqrt(vv / (REPS - 1) / REPS);
}

/* Welch t-test per block, Sidak-corrected alpha = 0.01 over all blocks plus the image mean.
 * Returns the number of failing blocks; *pmean gets the image-mean test's p-value. */
static int compare(const struct stack *a, const struct stack *b, double *pmean, double *worst)
{
    int n = a->w * a->h, fails = 0;
    double alpha = 1 - pow(0.99, 1.0 / (n + 1));
    *worst = 1;
    for (int i = 0; i < n; i++) {
        double se2 = a->v[i] + b->v[i];
        if (se2 == 0) {
            if (a->m[i] != b->m[i]) fails++;
            continue;
        }
        double tstat = fabs(a->m[i] - b->m[i]) / sqrt(se2), p = 2 * gsl_cdf_tdist_Q(tstat, 2 * REPS - 2);
        if (p < *worst) *worst = p;
        if (p < alpha) fails++;
    }
    double t = fabs(a->mean - b->mean) / sqrt(sqr(a->mean_se) + sqr(b->mean_se));
    *pmean = 2 * gsl_cdf_tdist_Q(t, 2 * REPS - 2);
    if (*pmean < alpha) fails++;
    return fails;
}

/* PT vs BDPT on the Cornell box at 64x64, 8 renders of 16 spp each per method, max length 8,
 * compared on 8x8 blocks (Welch t, alpha 0.01 Sidak over 65 comparisons). */
Test(stat_render, pt_agrees_with_bdpt_on_cornell_box)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 64, 64);
    static struct stack a, b;
    stack_runs(sc, METHOD_PT, 16, 8, 0, 0, 100, 8, &a);
    stack_runs(sc, METHOD_BDPT, 16, 8, 0, 0, 200, 8, &b);
    double pm, worst;
    int f = compare(&a, &b, &pm, &worst);
    cr_assert_eq(f, 0, "PT %g +- %g vs BDPT %g +- %g: %d failing comparisons (image mean p=%g, worst block p=%g)",
                 a.mean, a.mean_se, b.mean, b.mean_se, f, pm, worst);
    cr_assert(a.mean > 0);
    scene_free(sc);
}

/* Every technique of lengths 2 and 3 alone and unweighted (max length = k, so only paths of length
 * exactly k) against technique (1, k), light sampling: each is an unbiased estimator of the same
 * image, so this checks every contribution formula independently of the MIS weights.
 * 8 renders x 32 spp at 64x64 per technique; Welch t on 16x16 blocks (coarse, because techniques
 * such as (0, t) that must hit the small light are heavy-tailed), alpha 0.01 Sidak. */
Test(stat_render, every_technique_alone_is_unbiased)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 64, 64);
    static struct stack ref, a;
    for (int k = 2; k <= 3; k++) {
        stack_runs(sc, METHOD_BDPT, 32, k, 1, k, 300, 16, &ref); /* technique (1, k): light sampling */
        for (int s = 0; s <= k; s++) {
            if (s == 1) continue;
            stack_runs(sc, METHOD_BDPT, 32, k, s, k + 1 - s, 400 + 10 * s, 16, &a);
            double pm, worst;
            int f = compare(&a, &ref, &pm, &worst);
            cr_assert_eq(f, 0, "length %d: technique (%d,%d) %g +- %g vs (1,%d) %g +- %g: %d failing (mean p=%g)", k,
                         s, k + 1 - s, a.mean, a.mean_se, k, ref.mean, ref.mean_se, f, pm);
        }
    }
    scene_free(sc);
}
