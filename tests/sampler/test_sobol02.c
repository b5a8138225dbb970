/* Scrambled (0,2)-sequences (core/sampler/sobol02.h): the net property that makes them lower the
 * error, and that PT and BDPT stay unbiased with them and gain from them. */
#include <criterion/criterion.h>

#include "camera/camera.h"
#include "mc/render.h"
#include "path/scene_ready.h"
#include "sampler/sobol02.h"
#include "support/agree.h"
#include "support/scenes.h"
#include <math.h>
#include <string.h>

/* 2^m consecutive samples aligned at a multiple of 2^m, dimensions (2p, 2p + 1): every elementary
 * interval 2^-a x 2^-(m-a), a = 0..m, holds exactly one point. Exact (no statistics); checked for
 * m = 1..10, 6 keys, pairs 0..5 and blocks 0 and 3. Swapping the second dimension's generator for
 * the first (van der Corput twice) fails it at m = 2 (two points in a quarter). */
Test(sobol02, every_pair_of_dimensions_is_a_0_m_2_net)
{
    static int count[1 << 10];
    for (int m = 1; m <= 10; m++)
        for (uint64_t key = 1; key <= 6; key++)
            for (uint32_t pair = 0; pair < 6; pair++)
                for (uint32_t block = 0; block < 4; block += 3) {
                    int n = 1 << m;
                    for (int a = 0; a <= m; a++) {
                        memset(count, 0, sizeof(int) * (size_t)n);
                        for (int i = 0; i < n; i++) {
                            double x = sobol02_sample(key, block * (uint32_t)n + (uint32_t)i, 2 * pair);
                            double y = sobol02_sample(key, block * (uint32_t)n + (uint32_t)i, 2 * pair + 1);
                            cr_assert(x >= 0 && x < 1 && y >= 0 && y < 1);
                            int cx = (int)(x * (1 << a)), cy = (int)(y * (1 << (m - a)));
                            count[cx * (1 << (m - a)) + cy]++;
                        }
                        for (int c = 0; c < n; c++)
                            cr_assert_eq(count[c], 1,
                                         "m %d key %d pair %u block %u: interval %d of shape 2^-%d x 2^-%d holds %d", m,
                                         (int)key, pair, block, c, a, m - a, count[c]);
                    }
                }
}

/* Different pairs of one sample, and the same pair under different keys, are not the same points
 * (the padding that keeps a path's vertices from sharing their numbers): over 4096 samples the
 * correlation of dimension 0 with dimensions 2, 3 and with dimension 0 of another key is within
 * 4.5 standard errors of 0 (|r| < 4.5 / 64; alpha ~ 1e-5 for each of 3 comparisons). */
Test(sobol02, pairs_and_pixels_are_decorrelated)
{
    const int n = 4096;
    double sxx = 0, syy[3] = {0}, sxy[3] = {0};
    for (int i = 0; i < n; i++) {
        double x = sobol02_sample(7, (uint32_t)i, 0) - 0.5;
        double y[3] = {sobol02_sample(7, (uint32_t)i, 2) - 0.5, sobol02_sample(7, (uint32_t)i, 3) - 0.5,
                       sobol02_sample(8, (uint32_t)i, 0) - 0.5};
        sxx += x * x;
        for (int k = 0; k < 3; k++) {
            syy[k] += y[k] * y[k];
            sxy[k] += x * y[k];
        }
    }
    for (int k = 0; k < 3; k++) {
        double r = sxy[k] / sqrt(sxx * syy[k]);
        cr_assert(fabs(r) < 4.5 / sqrt(n), "comparison %d: correlation %g", k, r);
    }
}

struct sob_ctx {
    const struct scene *sc;
    enum method m;
    bool sobol;
    int spp;
};

static struct image *render_sob(void *p, uint64_t seed)
{
    struct sob_ctx *c = p;
    struct render_opts o = {
        .method = c->m, .spp = c->spp, .seed = seed, .threads = 2, .max_length = 8, .sobol = c->sobol};
    struct render_stats st;
    return render_mc(c->sc, &o, &st);
}

/* Unbiased: PT and BDPT with (0,2)-sequences against BDPT with independent numbers on the Cornell
 * box, 64x64, 8 renders of 16 spp per estimator, 8x8 blocks and the image mean (Welch t, alpha
 * 0.01 Sidak over 65 comparisons x 2 families). Without the padding (every pair reading the same
 * shuffled index with the same scrambles, so a bounce reuses the pixel's numbers) PT fails it: 41
 * comparisons, worst block p = 5e-13 (and the decorrelation test above: r = 1). Leaving the
 * values unscrambled does not fail it at this size (aligned blocks of Sobol points are nets too). */
Test(stat_sobol02, pt_and_bdpt_with_sobol_agree_with_independent_bdpt)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 64, 64);
    static struct stack ref, a;
    struct sob_ctx r = {sc, METHOD_BDPT, false, 16};
    stack_runs(&ref, render_sob, &r, 8, 500, 8);
    for (int m = 0; m < 2; m++) {
        struct sob_ctx c = {sc, (enum method)m, true, 16};
        stack_runs(&a, render_sob, &c, 8, 600 + 10 * (uint64_t)m, 8);
        double pm, worst;
        int f = stack_compare(&a, &ref, 2, &pm, &worst);
        cr_assert_eq(f, 0, "%s sobol %g +- %g vs bdpt %g +- %g: %d failing (mean p=%g, worst block p=%g)",
                     method_name((enum method)m), a.mean, a.mean_se, ref.mean, ref.mean_se, f, pm, worst);
    }
    scene_free(sc);
}

/* And better: per-pixel squared error against a 1024-spp independent BDPT reference, PT at 16 spp
 * on the Cornell box (64x64), summed over the image, 6 seeds per sampler: the mean over seeds with
 * (0,2)-sequences is below the independent one's by more than 3 standard errors of the difference
 * (the direct-lighting dimensions, pixel and first bounce, are where it gains). */
Test(stat_sobol02, sobol_lowers_pt_error_on_cornell_box)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 64, 64);
    struct render_opts ro = {.method = METHOD_BDPT, .spp = 1024, .seed = 77, .threads = 2, .max_length = 8};
    struct render_stats st;
    struct image *ref = render_mc(sc, &ro, &st);
    double e[2][6];
    for (int q = 0; q < 2; q++)
        for (int s = 0; s < 6; s++) {
            struct sob_ctx c = {sc, METHOD_PT, q == 1, 16};
            struct image *im = render_sob(&c, 900 + (uint64_t)s);
            double sum = 0;
            for (int y = 0; y < 64; y++)
                for (int x = 0; x < 64; x++) {
                    vec3 d = vsub(img_get(im, x, y), img_get(ref, x, y));
                    sum += vdot(d, d);
                }
            e[q][s] = sum;
            img_destroy(im);
        }
    double m[2], v[2];
    for (int q = 0; q < 2; q++) {
        m[q] = v[q] = 0;
        for (int s = 0; s < 6; s++)
            m[q] += e[q][s] / 6;
        for (int s = 0; s < 6; s++)
            v[q] += (e[q][s] - m[q]) * (e[q][s] - m[q]) / 5;
    }
    double z = (m[0] - m[1]) / sqrt(v[0] / 6 + v[1] / 6);
    fprintf(stderr, "sobol02: PT 16 spp squared error independent %.4g, sobol %.4g (ratio %.3f), z %.1f\n", m[0], m[1],
            m[1] / m[0], z);
    cr_assert(z > 3, "independent %g vs sobol %g: z = %g", m[0], m[1], z);
    img_destroy(ref);
    scene_free(sc);
}
