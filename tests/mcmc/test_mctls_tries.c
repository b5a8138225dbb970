/* MCTLS with a fixed number of drawn trials (mlt_opts.mctls_tries, Eq. 4.5 of the thesis; the
 * analysis runs of fig4.5): the chain stays unbiased with 2 trials, and with 1 trial drawn among
 * the thesis's k + 2 techniques (t = 0 always failing); the option's refusals. */
#include <criterion/criterion.h>

#include "camera/camera.h"
#include "mc/render.h"
#include "mcmc/mctls.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include "support/agree.h"
#include "support/disk_cache.h"
#include "support/scenes.h"
#include <stdio.h>
#include <string.h>

static struct image *render_bdpt(void *p, uint64_t seed)
{
    struct render_opts o = {.method = METHOD_BDPT, .spp = 16, .seed = seed, .threads = 2, .max_length = 8};
    struct render_stats st;
    return render_mc(p, &o, &st);
}

/* Cornell box at 64x64: 8 BDPT renders of 16 spp against 12 MMLT runs of 16 mutations per pixel
 * (p_large = 0.5, 10k seed paths each) per configuration; Welch t on 8x8 blocks and the image mean,
 * alpha = 0.01 Sidak over the 2 x 65 comparisons. A denominator without the drawn variates (the
 * current state's own target alone) fails it: checked once by hand. */
Test(stat_mctls_tries, drawn_trials_agree_with_bdpt_on_cornell_box, .timeout = 600)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 64, 64);
    static struct stack ref, a;
    /* the reference of stat_mlt/mcmc_agrees_with_bdpt_on_cornell_box: rendered once for both */
    stack_runs_cached(&ref, render_bdpt, sc, 8, 1000, 8, sc, "bdpt spp 16 threads 2 max_length 8");
    const struct {
        const char *name;
        int tries;
        bool t0;
    } cfg[] = {{"2 trials", 2, false}, {"1 trial among k + 2", 1, true}};
    const int n = sizeof cfg / sizeof *cfg;
    for (int i = 0; i < n; i++) {
        struct mlt_ctx c = {sc,
                            {.method = MLT_MMLT,
                             .p_large = 0.5,
                             .mutations = 16L * 64 * 64,
                             .seed_paths = 10000,
                             .threads = 2,
                             .max_length = 8,
                             .large_step = LARGE_MCTLS,
                             .mctls_tries = cfg[i].tries,
                             .mctls_count_t0 = cfg[i].t0}};
        pss_opts_default(&c.o.pss, 64, 64);
        stack_runs(&a, render_mlt, &c, 12, 5000 + 100 * i, 8);
        double pm, worst;
        int f = stack_compare(&a, &ref, n, &pm, &worst);
        fprintf(stderr, "cornell mctls %s: %g +- %g vs BDPT %g +- %g (mean p=%.3g, worst block p=%.3g)\n", cfg[i].name,
                a.mean, a.mean_se, ref.mean, ref.mean_se, pm, worst);
        cr_assert_eq(f, 0, "%s: %d failing (mean p=%g, worst block p=%g)", cfg[i].name, f, pm, worst);
    }
    scene_free(sc);
}

/* The combinations mlt_render refuses, each with one message. */
Test(mctls_tries, refused_combinations)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 16, 16);
    const struct {
        enum mlt_method m;
        enum large_step ls;
        int tries;
        bool t0;
    } bad[] = {{MLT_MMLT, LARGE_MMLT, 2, false},
               {MLT_PSSMLT, LARGE_MCTLS, 2, false},
               {MLT_MMLT, LARGE_MCTLS, 0, true},
               {MLT_MMLT, LARGE_MCTLS, MCTLS_MAX_TRIES + 1, false},
               {MLT_MMLT, LARGE_MCTLS, -1, false}};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        struct mlt_opts o = {.method = bad[i].m,
                             .p_large = 0.5,
                             .mutations = 1000,
                             .seed_paths = 1000,
                             .threads = 1,
                             .max_length = 4,
                             .large_step = bad[i].ls,
                             .mctls_tries = bad[i].tries,
                             .mctls_count_t0 = bad[i].t0};
        pss_opts_default(&o.pss, 16, 16);
        struct mlt_result r;
        char err[256] = "";
        cr_assert_not(mlt_render(sc, &o, &r, err, sizeof err), "case %zu accepted", i);
        cr_assert(strstr(err, "MCTLS trials"), "case %zu: %s", i, err);
    }
    scene_free(sc);
}
