/* Environment emitters in every method. scenes/sky-sphere: a convex lambert sphere (albedo 0.5)
 * under a constant white sky has radiance exactly 0.5, which holds only if escaping paths, light
 * samples toward the sky and (for BDPT) emitter subpaths started from the sky are weighted
 * consistently. scenes/sky-courtyard: a textured sky plus an area light, where PT, PSSMLT, MMLT and
 * PITP must agree with BDPT per block. */
#include <criterion/criterion.h>

#include "camera/camera.h"
#include "mc/render.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include "support/agree.h"
#include "support/scenes.h"
#include <gsl/gsl_cdf.h>

/* One PSSMLT or MMLT run of mpp mutations per pixel on 2 threads, p_large 0.1. */
static struct image *mcmc_run(const struct scene *sc, enum mlt_method m, long mpp, long seed_paths, uint64_t seed,
                              int max_length)
{
    struct mlt_opts mo = {.method = m,
                          .p_large = 0.1,
                          .pitp_rate = 1,
                          .mutations = mpp * sc->cam.width * sc->cam.height,
                          .seed_paths = seed_paths,
                          .seed = seed,
                          .threads = 2,
                          .max_length = max_length};
    pss_opts_default(&mo.pss, sc->cam.width, sc->cam.height);
    struct mlt_result res;
    char err[256];
    cr_assert(mlt_render(sc, &mo, &res, err, sizeof err), "%s", err);
    return res.img;
}

/* Mean green value of the centre 8x8 pixels of the 32x32 image, which lie on the sphere. */
static double centre_mean(const struct image *im, double *se)
{
    double s = 0, s2 = 0;
    for (int y = 12; y < 20; y++)
        for (int x = 12; x < 20; x++) {
            double v = img_get(im, x, y).y;
            s += v;
            s2 += v * v;
        }
    double mean = s / 64;
    *se = sqrt(fmax(0, s2 / 64 - mean * mean) / 63);
    return mean;
}

/* PT and BDPT: the centre's mean must be 0.5 within 4 standard errors (pixel spread, 64 pixels)
 * and 1 %; 256 spp, seeds 3 and 4. PSSMLT and MMLT, whose pixels are correlated: the centre's mean
 * over 8 runs of 1024 mutations per pixel (100k seed paths) must contain 0.5 (t-test, alpha 0.01
 * Sidak over the 2 methods) and lie within 4 %. MMLT runs of this length scatter by about 2 %
 * (40 of them averaged 0.5040 +- 0.0029). MMLT with lengths >= 2 weighted by 0.95 fails it
 * (0.459 +- 0.005, t = -9.0 against a threshold of 4.0). */
Test(stat_env, constant_sky_sphere_every_method)
{
    struct scene *sc = test_scene("scenes/sky-sphere/scene.json");
    double se;
    for (int m = 0; m < 2; m++) {
        struct render_opts o = {
            .method = (enum method)m, .spp = 256, .seed = 3 + (uint64_t)m, .threads = 2, .max_length = 4};
        struct render_stats st;
        struct image *im = render_mc(sc, &o, &st);
        double mean = centre_mean(im, &se);
        cr_assert(fabs(mean - 0.5) < 4 * se + 1e-12 && fabs(mean - 0.5) < 0.005,
                  "%s: sphere radiance %g +- %g, expected 0.5", method_name((enum method)m), mean, se);
        if (m == METHOD_PT) cr_assert(fabs(img_get(im, 0, 0).x - 1) < 1e-12, "pt: background is not 1");
        img_destroy(im);
    }
    double tmax = gsl_cdf_tdist_Qinv((1 - pow(0.99, 1.0 / 3)) / 2, 7);
    for (int m = 0; m < 3; m++) {
        double s = 0, s2 = 0;
        for (int r = 0; r < 8; r++) {
            struct image *im = mcmc_run(sc, (enum mlt_method)m, 1024, 100000, 130 + 10 * (uint64_t)m + (uint64_t)r, 4);
            double v = centre_mean(im, &se);
            s += v;
            s2 += v * v;
            img_destroy(im);
        }
        double mean = s / 8, run_se = sqrt(fmax(0, s2 / 8 - mean * mean) / 7);
        fprintf(stderr, "sky sphere %s: %.6f +- %.6f, expected 0.5 (t = %.2f, limit %.2f)\n",
                (const char *[]){"pssmlt", "mmlt", "pitp"}[m], mean, run_se, (mean - 0.5) / run_se, tmax);
        cr_assert(fabs(mean - 0.5) < tmax * run_se + 1e-12 && fabs(mean - 0.5) < 0.04,
                  "%s: sphere radiance %.6f +- %.6f, expected 0.5", (const char *[]){"pssmlt", "mmlt", "pitp"}[m], mean,
                  run_se);
    }
    scene_free(sc);
}

struct ctx {
    const struct scene *sc;
    enum method mc;
    int mlt; /* -1: Monte Carlo, else enum mlt_method */
};

static struct image *render_any(void *p, uint64_t seed)
{
    struct ctx *c = p;
    if (c->mlt < 0) {
        struct render_opts o = {.method = c->mc, .spp = 16, .seed = seed, .threads = 2, .max_length = 6};
        struct render_stats st;
        return render_mc(c->sc, &o, &st);
    }
    return mcmc_run(c->sc, (enum mlt_method)c->mlt, 16, 10000, seed, 6);
}

/* 64x48 pixels; 8 BDPT runs of 16 spp against 8 PT runs (16 spp) and 12 PSSMLT / MMLT / PITP runs
 * (16 mutations per pixel); Welch t on 8x8 blocks + image mean, alpha 0.01 Sidak over 4 comparisons. */
Test(stat_env, textured_sky_all_methods_agree_with_bdpt)
{
    struct scene *sc = test_scene("scenes/sky-courtyard/scene.json");
    camera_resize(&sc->cam, 64, 48);
    static struct stack ref, a;
    struct ctx r = {sc, METHOD_BDPT, -1};
    stack_runs(&ref, render_any, &r, 8, 500, 8);
    const struct ctx cfg[] = {
        {sc, METHOD_PT, -1}, {sc, METHOD_BDPT, MLT_PSSMLT}, {sc, METHOD_BDPT, MLT_MMLT}, {sc, METHOD_BDPT, MLT_PITP}};
    const char *names[] = {"pt", "pssmlt", "mmlt", "pitp"};
    for (int i = 0; i < 4; i++) {
        struct ctx c = cfg[i];
        stack_runs(&a, render_any, &c, i ? 12 : 8, 600 + 50 * (uint64_t)i, 8);
        double pm, worst;
        int f = stack_compare(&a, &ref, 4, &pm, &worst);
        fprintf(stderr, "sky-courtyard %s: %g +- %g vs BDPT %g +- %g (mean p=%.3g, worst block p=%.3g)\n", names[i],
                a.mean, a.mean_se, ref.mean, ref.mean_se, pm, worst);
        cr_assert_eq(f, 0, "%s: %g +- %g vs BDPT %g +- %g: %d failing (mean p=%g, worst block p=%g)", names[i], a.mean,
                     a.mean_se, ref.mean, ref.mean_se, f, pm, worst);
    }
    scene_free(sc);
}

/* tests/data/specular-furnace.json: a glass sphere and a mirror sphere (albedo 1) under a constant
 * white sky. Nothing absorbs, so every pixel is 1, up to paths still inside the glass after 16
 * segments. A path that reaches the sky through a delta bounce has one technique only (escaping:
 * no light sample or connection can pass a delta vertex), so its MIS weight must be exactly 1.
 * PT has no other noise: every pixel must be 1 to 1e-6. BDPT (light tracing of the directly seen
 * sky), PSSMLT, MMLT and PITP are noisy: their image mean over 8 runs (BDPT 16 spp, MCMC 64
 * mutations per pixel) must contain 1 (t-test, alpha 0.01 Sidak over the 4 methods) and lie within
 * 2 %. */
Test(stat_env, specular_spheres_under_white_sky_are_exactly_white)
{
    struct scene *sc = test_scene("tests/data/specular-furnace.json");
    struct render_opts o = {.method = METHOD_PT, .spp = 16, .seed = 1, .threads = 2, .max_length = 16};
    struct render_stats st;
    struct image *im = render_mc(sc, &o, &st);
    for (int i = 0; i < im->w * im->h * 3; i++)
        cr_assert(fabs(im->px[i] - 1) < 1e-6, "pt: a pixel reads %.9g", im->px[i]);
    img_destroy(im);
    double tmax = gsl_cdf_tdist_Qinv((1 - pow(0.99, 1.0 / 4)) / 2, 7);
    const char *names[] = {"bdpt", "pssmlt", "mmlt", "pitp"};
    for (int m = 0; m < 4; m++) {
        double s = 0, s2 = 0;
        for (int r = 0; r < 8; r++) {
            struct image *x;
            if (m == 0) {
                o.method = METHOD_BDPT;
                o.seed = 10 + (uint64_t)r;
                x = render_mc(sc, &o, &st);
            } else {
                x = mcmc_run(sc, (enum mlt_method)(m - 1), 64, 10000, 20 + 10 * (uint64_t)m + (uint64_t)r, 16);
            }
            double v = img_mean_luminance(x);
            s += v;
            s2 += v * v;
            img_destroy(x);
        }
        double mean = s / 8, se = sqrt(fmax(0, s2 / 8 - mean * mean) / 7);
        fprintf(stderr, "specular furnace %s: %.6f +- %.6f, expected 1\n", names[m], mean, se);
        cr_assert(fabs(mean - 1) < tmax * se + 1e-12 && fabs(mean - 1) < 0.02,
                  "%s: image mean %.6f +- %.6f, expected 1", names[m], mean, se);
    }
    scene_free(sc);
}
