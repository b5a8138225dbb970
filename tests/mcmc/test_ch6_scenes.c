/* scenes/living-room and scenes/staircase (thesis chapter 6, built for this harness): PT, PSSMLT and
 * MMLT against BDPT, per 8x8 block and on the image mean (tests/agree.h), as the other scenes are
 * tested in test_mlt.c. Both scenes are lit only by a generated sky with a small sun, through a
 * window or a skylight, so most light arrives by long paths that pass an opening. */
#include <criterion/criterion.h>
#include <criterion/parameterized.h>

#include "camera/camera.h"
#include "mc/render.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include "support/agree.h"
#include "support/disk_cache.h"
#include "support/scenes.h"

struct ch6_run {
    const struct scene *sc;
    bool mcmc;
    enum method mc;
    enum mlt_method mlt;
    long per_pixel; /* samples or mutations per pixel */
    long seed_paths;
    int min_length;     /* --min-length */
    int subtract_below; /* > 0: BDPT with all lengths minus an independent BDPT run of lengths < this */
};

static struct image *ch6_render(void *p, uint64_t seed)
{
    const struct ch6_run *c = p;
    if (!c->mcmc) {
        struct render_opts o = {.method = c->mc,
                                .spp = (int)c->per_pixel,
                                .seed = seed,
                                .threads = 2,
                                .max_length = 8,
                                .min_length = c->min_length};
        struct render_stats st;
        struct image *im = render_mc(c->sc, &o, &st);
        if (c->subtract_below > 0) {
            o.max_length = c->subtract_below - 1;
            o.seed = seed + 100000;
            struct image *lo = render_mc(c->sc, &o, &st);
            img_accumulate(im, lo, -1);
            img_destroy(lo);
        }
        return im;
    }
    struct mlt_opts o = {.method = c->mlt,
                         .p_large = 0.1,
                         .pitp_rate = 1,
                         .seed_paths = c->seed_paths,
                         .seed = seed,
                         .threads = 2,
                         .max_length = 8,
                         .min_length = c->min_length,
                         .mutations = c->per_pixel * c->sc->cam.width * c->sc->cam.height};
    pss_opts_default(&o.pss, c->sc->cam.width, c->sc->cam.height);
    struct mlt_result r;
    char err[256];
    cr_assert(mlt_render(c->sc, &o, &r, err, sizeof err), "%s", err);
    cr_assert_eq(r.nonfinite, 0);
    struct image *im = r.img;
    r.img = NULL;
    mlt_result_free(&r);
    return im;
}

/* 8 BDPT runs as the reference; 8 PT and 12 PSSMLT, MMLT and PITP runs, each family tested against it
 * (alpha 0.01, Sidak over the 4 families' blocks and means). One family (m: pt, pssmlt, mmlt, pitp)
 * per test, so that --jobs spreads them; the reference is rendered once (support/disk_cache.h). */
static void ch6_agree(const char *path, int res, int bdpt_spp, int pt_spp, int pss_mpp, int mmlt_mpp, long seed_paths,
                      uint64_t seed, int m)
{
    struct scene *sc = test_scene(path);
    camera_resize(&sc->cam, res, res);
    static struct stack ref, a;
    struct ch6_run bd = {.sc = sc, .mc = METHOD_BDPT, .per_pixel = bdpt_spp};
    char key[96];
    snprintf(key, sizeof key, "bdpt spp %d threads 2 max_length 8", bdpt_spp);
    stack_runs_cached(&ref, ch6_render, &bd, 8, seed, 8, sc, key);
    const struct ch6_run runs[4] = {
        {.sc = sc, .mc = METHOD_PT, .per_pixel = pt_spp},
        {.sc = sc, .mcmc = true, .mlt = MLT_PSSMLT, .per_pixel = pss_mpp, .seed_paths = seed_paths},
        {.sc = sc, .mcmc = true, .mlt = MLT_MMLT, .per_pixel = mmlt_mpp, .seed_paths = seed_paths},
        {.sc = sc, .mcmc = true, .mlt = MLT_PITP, .per_pixel = mmlt_mpp, .seed_paths = seed_paths}};
    const char *names[4] = {"pt", "pssmlt", "mmlt", "pitp"};
    double pm, worst;
    stack_runs(&a, ch6_render, (void *)&runs[m], m == 0 ? 8 : 12, seed + 100 * (uint64_t)(m + 1), 8);
    int f = stack_compare(&a, &ref, 4, &pm, &worst);
    cr_assert_eq(f, 0, "%s on %s: %g +- %g vs BDPT %g +- %g: %d failing (mean p=%g, worst block p=%g)", names[m], path,
                 a.mean, a.mean_se, ref.mean, ref.mean_se, f, pm, worst);
    scene_free(sc);
}

ParameterizedTestParameters(stat_ch6, all_methods_agree_on_living_room)
{
    static int m[] = {0, 1, 2, 3};
    return cr_make_param_array(int, m, 4);
}
ParameterizedTest(int *m, stat_ch6, all_methods_agree_on_living_room, .timeout = 600)
{
    ch6_agree("scenes/living-room/scene.json", 32, 64, 256, 256, 256, 100000, 5000, *m);
}

ParameterizedTestParameters(stat_ch6, all_methods_agree_on_staircase)
{
    static int m[] = {0, 1, 2, 3};
    return cr_make_param_array(int, m, 4);
}
ParameterizedTest(int *m, stat_ch6, all_methods_agree_on_staircase, .timeout = 600)
{
    ch6_agree("scenes/staircase/scene.json", 32, 64, 256, 256, 256, 100000, 6000, *m);
}

/* --min-length 3 (no direct lighting, as thesis chapter 6 renders) for every method: PT, BDPT, PSSMLT
 * MMLT and PITP with lengths >= 3 only against BDPT with all lengths minus an independent BDPT run of
 * lengths 1-2 (an unbiased estimate of the same light), Cornell box at 32x32. */
Test(stat_ch6, min_length_leaves_out_exactly_the_shorter_paths, .timeout = 600)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 32, 32);
    static struct stack ref, a;
    struct ch6_run diff = {.sc = sc, .mc = METHOD_BDPT, .per_pixel = 64, .subtract_below = 3};
    stack_runs(&ref, ch6_render, &diff, 8, 9000, 8);
    const struct ch6_run runs[5] = {
        {.sc = sc, .mc = METHOD_PT, .per_pixel = 128, .min_length = 3},
        {.sc = sc, .mc = METHOD_BDPT, .per_pixel = 32, .min_length = 3},
        {.sc = sc, .mcmc = true, .mlt = MLT_PSSMLT, .per_pixel = 64, .seed_paths = 20000, .min_length = 3},
        {.sc = sc, .mcmc = true, .mlt = MLT_MMLT, .per_pixel = 64, .seed_paths = 20000, .min_length = 3},
        {.sc = sc, .mcmc = true, .mlt = MLT_PITP, .per_pixel = 64, .seed_paths = 20000, .min_length = 3}};
    const char *names[5] = {"pt", "bdpt", "pssmlt", "mmlt", "pitp"};
    for (int m = 0; m < 5; m++) {
        double pm, worst;
        stack_runs(&a, ch6_render, (void *)&runs[m], m < 2 ? 8 : 12, 9100 + 100 * m, 8);
        int f = stack_compare(&a, &ref, 5, &pm, &worst);
        cr_assert_eq(f, 0,
                     "%s --min-length 3: %g +- %g vs BDPT difference %g +- %g: %d failing (mean p=%g, worst p=%g)",
                     names[m], a.mean, a.mean_se, ref.mean, ref.mean_se, f, pm, worst);
    }
    /* and it is not the full image: the direct light is a large share of the Cornell box */
    struct ch6_run full = {.sc = sc, .mc = METHOD_BDPT, .per_pixel = 32};
    stack_runs(&a, ch6_render, &full, 4, 9900, 8);
    cr_assert_gt(a.mean, 1.5 * ref.mean, "full %g vs lengths >= 3 %g", a.mean, ref.mean);
    scene_free(sc);
}
