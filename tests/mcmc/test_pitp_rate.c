/* PITP's technique-perturbation rate (--pitp-rate P, mlt.h): at P = 0 it is MMLT, bit for bit; the
 * perturbation precedes a small step with probability P; and at every P tested the image agrees
 * with BDPT on the Cornell box, since each kernel of the mixture keeps the target. */
#include <criterion/criterion.h>
#include <criterion/parameterized.h>

#include "camera/camera.h"
#include "mc/render.h"
#include "mcmc/mlt_options.h"
#include "path/scene_ready.h"
#include "support/agree.h"
#include "support/disk_cache.h"
#include "support/scenes.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

static void opts(struct mlt_opts *o, const struct scene *sc, enum mlt_method m, double rate, long mutations)
{
    mlt_opts_defaults(o);
    o->method = m;
    o->pitp_rate = rate;
    o->mutations = mutations;
    o->seed_paths = 10000;
    o->threads = 2;
    o->max_length = 8;
    o->seed = 5;
    pss_opts_default(&o->pss, sc->cam.width, sc->cam.height);
}

/* At P = 0 no decision is drawn and the perturbation never runs: the chains draw exactly MMLT's
 * numbers (PITP keeps its path in the chain, which draws nothing), so the image is MMLT's bit for
 * bit. */
Test(pitp_rate, zero_is_mmlt_bit_for_bit)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 32, 32);
    struct mlt_opts o;
    struct mlt_result a, b;
    opts(&o, sc, MLT_PITP, 0, 16L * 32 * 32);
    mlt_render_ok(sc, &o, &a);
    opts(&o, sc, MLT_MMLT, 1, 16L * 32 * 32);
    mlt_render_ok(sc, &o, &b);
    cr_assert_eq(a.stats.total[PROPOSAL_PITP].attempts, 0);
    cr_assert_eq(a.mutations, b.mutations);
    size_t n = (size_t)a.img->w * (size_t)a.img->h * 3;
    cr_assert(a.img->w == b.img->w && a.img->h == b.img->h);
    cr_assert(!memcmp(a.img->px, b.img->px, n * sizeof *a.img->px), "pitp --pitp-rate 0 differs from mmlt");
    mlt_result_free(&a);
    mlt_result_free(&b);
    scene_free(sc);
}

/* The decision is a Bernoulli(P) draw per small step, independent of everything else, so the
 * perturbations are Binomial(small steps, P): two-sided z-test at alpha = 0.001 per rate (Sidak over
 * the three: 0.0033 overall), about 59 000 small steps each. */
Test(pitp_rate, perturbations_precede_a_share_p_of_small_steps)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 64, 64);
    const double rates[] = {0.05, 0.5, 0.9};
    for (int i = 0; i < 3; i++) {
        struct mlt_opts o;
        struct mlt_result r;
        opts(&o, sc, MLT_PITP, rates[i], 16L * 64 * 64);
        mlt_render_ok(sc, &o, &r);
        double n = (double)r.stats.total[PROPOSAL_SMALL].attempts, x = (double)r.stats.total[PROPOSAL_PITP].attempts;
        double p = rates[i], z = (x - n * p) / sqrt(n * p * (1 - p));
        fprintf(stderr, "pitp rate %g: %.0f perturbations before %.0f small steps (z = %.2f)\n", p, x, n, z);
        cr_expect_lt(fabs(z), 3.29, "rate %g: %.0f of %.0f small steps (z = %.2f)", p, x, n, z);
        mlt_result_free(&r);
    }
    scene_free(sc);
}

static struct image *render_bdpt(void *p, uint64_t seed)
{
    const struct scene *sc = p;
    struct render_opts o = {.method = METHOD_BDPT, .spp = 16, .seed = seed, .threads = 2, .max_length = 8};
    struct render_stats st;
    return render_mc(sc, &o, &st);
}

/* Cornell box at 64x64, as stat_mlt/mcmc_agrees_with_bdpt_on_cornell_box (its cached reference: 8
 * BDPT renders of 16 spp): 12 independent PITP runs of 16 mutations per pixel per rate; Welch t on
 * 8x8 blocks and on the image mean, alpha 0.01 Sidak over the 65 comparisons of each of the 3 rates. */
static const double agree_rates[] = {0, 0.05, 0.5};
#define AGREE_RATES ((int)(sizeof agree_rates / sizeof *agree_rates))

ParameterizedTestParameters(stat_pitp_rate, agrees_with_bdpt_on_cornell_box)
{
    static int idx[AGREE_RATES];
    for (int i = 0; i < AGREE_RATES; i++)
        idx[i] = i;
    return cr_make_param_array(int, idx, AGREE_RATES);
}

ParameterizedTest(int *param, stat_pitp_rate, agrees_with_bdpt_on_cornell_box)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 64, 64);
    static struct stack ref, a;
    stack_runs_cached(&ref, render_bdpt, sc, 8, 1000, 8, sc, "bdpt spp 16 threads 2 max_length 8");
    double rate = agree_rates[*param];
    struct mlt_ctx c = {sc, {0}};
    opts(&c.o, sc, MLT_PITP, rate, 16L * 64 * 64);
    c.o.p_large = 0.1;
    stack_runs(&a, render_mlt, &c, 12, 7000 + 100 * (uint64_t)*param, 8);
    double pm, worst;
    int f = stack_compare(&a, &ref, AGREE_RATES, &pm, &worst);
    fprintf(stderr, "cornell pitp --pitp-rate %g: %g +- %g vs BDPT %g +- %g (mean p=%.3g, worst block p=%.3g)\n", rate,
            a.mean, a.mean_se, ref.mean, ref.mean_se, pm, worst);
    cr_assert_eq(f, 0, "rate %g: %g +- %g vs BDPT %g +- %g: %d failing (mean p=%g, worst block p=%g)", rate, a.mean,
                 a.mean_se, ref.mean, ref.mean_se, f, pm, worst);
    scene_free(sc);
}
