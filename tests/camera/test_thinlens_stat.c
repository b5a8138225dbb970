/* Thin-lens camera, statistical: the importance is normalised over film and aperture, and the
 * techniques that meet the lens from either side agree (path tracing reaches it by camera rays,
 * light tracing by connections to a lens point, t = 1). */
#include <criterion/criterion.h>
#include <criterion/parameterized.h>
#include <stdio.h>

#include "camera/camera.h"
#include "mc/render.h"
#include "mcmc/controlled_step.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include "support/agree.h"
#include "support/disk_cache.h"
#include "support/scenes.h"

#define SCENE "tests/data/tungsten/camera-thinlens.json"

/* Integral of We(p, d) = p_lens(p) camera_pdf_dir(p, d) over the lens plane (area) and directions
 * (solid angle): 1. Plain Monte Carlo, N = 2M, p uniform on the square around the aperture (We = 0
 * off the disc), d uniform in tangent space over a window that holds the film seen from every lens
 * point (dw = cos^3 dx dy). Tolerance 5 standard errors estimated from the same samples (a false
 * alarm about 1 in 1.7M). Box and tent film. */
static void importance_integral(enum recon_filter f, uint64_t seed)
{
    struct scene *sc = test_scene(SCENE);
    struct camera c = sc->cam;
    c.filter = f;
    double R = c.lens_radius, m = camera_margin(&c);
    double X = c.tan_half_fov * (1 + 2 * m / c.width) + R / c.focus_dist + 0.01;
    double Y = c.tan_half_fov / c.aspect * (1 + 2 * m / c.height) + R / c.focus_dist + 0.01;
    double scale = (2 * R) * (2 * R) * (2 * X) * (2 * Y);
    rng r;
    rng_seed(&r, seed, 0);
    const int N = 2000000;
    double s = 0, s2 = 0;
    for (int i = 0; i < N; i++) {
        double a = (2 * rng_uniform(&r) - 1) * R, b = (2 * rng_uniform(&r) - 1) * R;
        double x = (2 * rng_uniform(&r) - 1) * X, y = (2 * rng_uniform(&r) - 1) * Y;
        double v = 0;
        if (a * a + b * b <= R * R) {
            vec3 lens = vadd(c.pos, vadd(vscale(c.basis.s, a), vscale(c.basis.t, b)));
            vec3 l = v3(x, y, 1);
            double len = vlen(l), ct = 1 / len;
            vec3 d = vscale(frame_to_world(&c.basis, l), 1 / len);
            double px, py, we = camera_raster(&c, lens, d, &px, &py) / (M_PI * R * R);
            v = we * ct * ct * ct * scale;
        }
        s += v;
        s2 += v * v;
    }
    double mean = s / N, se = sqrt((s2 / N - mean * mean) / N);
    fprintf(stderr, "thinlens %s: integral of We over film and aperture %.5f +- %.5f (N %d)\n",
            f == FILTER_BOX ? "box" : "tent", mean, se, N);
    cr_assert(fabs(mean - 1) < 5 * se, "integral of We = %g +- %g", mean, se);
    scene_free(sc);
}
Test(stat_thinlens, importance_normalised_box) { importance_integral(FILTER_BOX, 41); }
Test(stat_thinlens, importance_normalised_tent) { importance_integral(FILTER_TENT, 43); }

struct run {
    const struct scene *sc;
    struct render_opts o;
};
static struct image *render_run(void *p, uint64_t seed)
{
    struct run *r = p;
    struct render_opts o = r->o;
    o.seed = seed;
    struct render_stats st;
    struct image *im = render_mc(r->sc, &o, &st);
    cr_assert_eq(st.nonfinite, 0);
    return im;
}

/* PT against BDPT on the thin-lens scene (80 x 60, paths up to 4 segments), and light tracing
 * alone (technique s = 2, t = 1, unweighted: every path of 2 segments by a connection to a lens
 * point) against PT restricted to 2 segments. 8 replicate renders each, blocks and the image mean,
 * Welch t-tests at alpha = 0.01 Sidak-corrected over the blocks and the mean of both comparisons
 * (stack_compare). Blocks of 8 x 8 pixels; 16 x 16 for light tracing alone, whose rare large
 * splats in the darkest blocks (a contact shadow at 1e-4 of the image mean) left a block at 0 in
 * all 8 replicates where PT has 9e-6 +- 9e-7: a zero-variance sample that Welch's test cannot
 * weigh. */
Test(stat_thinlens, pt_bdpt_and_light_tracing_agree, .timeout = 300)
{
    struct scene *sc = test_scene(SCENE);
    struct stack pt, bd, pt2, lt;
    struct run a = {sc, {.method = METHOD_PT, .spp = 64, .threads = 2, .max_length = 4}};
    struct run b = {sc, {.method = METHOD_BDPT, .spp = 32, .threads = 2, .max_length = 4}};
    struct run c = {sc, {.method = METHOD_PT, .spp = 64, .threads = 2, .max_length = 2, .min_length = 2}};
    struct run d = {sc, {.method = METHOD_BDPT, .spp = 16, .threads = 2, .max_length = 2, .only_s = 2, .only_t = 1}};
    stack_runs(&pt, render_run, &a, 8, 100, 8);
    stack_runs(&bd, render_run, &b, 8, 200, 8);
    stack_runs(&pt2, render_run, &c, 8, 300, 16);
    stack_runs(&lt, render_run, &d, 8, 400, 16);
    double pm, worst, pm2, worst2;
    int f = stack_compare(&pt, &bd, 2, &pm, &worst), f2 = stack_compare(&pt2, &lt, 2, &pm2, &worst2);
    fprintf(stderr, "thinlens PT %g +- %g vs BDPT %g +- %g: %d failing (mean p %.3g, worst block p %.3g)\n", pt.mean,
            pt.mean_se, bd.mean, bd.mean_se, f, pm, worst);
    fprintf(stderr,
            "thinlens length 2: PT %g +- %g vs light tracing %g +- %g: %d failing (mean p %.3g, worst block p %.3g)\n",
            pt2.mean, pt2.mean_se, lt.mean, lt.mean_se, f2, pm2, worst2);
    cr_assert_eq(f, 0, "PT vs BDPT: %d comparisons fail", f);
    cr_assert_eq(f2, 0, "PT vs light tracing: %d comparisons fail", f2);
    scene_free(sc);
}

struct chain_run {
    const struct scene *sc;
    enum mlt_method m;
    enum small_step step;
};
/* One MCMC render of 64 mutations per pixel (20k seed paths), 2 threads, p_large 0.1. */
static struct image *chain_render(void *p, uint64_t seed)
{
    struct chain_run *c = p;
    const struct scene *sc = c->sc;
    struct mlt_opts mo = {.method = c->m,
                          .p_large = 0.1,
                          .pitp_rate = 1,
                          .mutations = 64L * sc->cam.width * sc->cam.height,
                          .seed_paths = 20000,
                          .seed = seed,
                          .threads = 2,
                          .max_length = 4,
                          .small_step = c->step};
    pss_opts_default(&mo.pss, sc->cam.width, sc->cam.height);
    if (c->step == SMALL_STEP_CONTROLLED) mo.pss.kernel = KERNEL_GAUSSIAN;
    struct mlt_result res;
    char err[256];
    cr_assert(mlt_render(sc, &mo, &res, err, sizeof err), "%s", err);
    return res.img;
}

/* The Markov-chain methods on the thin lens (their camera vertex is the lens point, its numbers the
 * first two of camera block 0; PITP grows and shrinks camera subpaths through t = 1): PSSMLT, MMLT,
 * PITP and MMLT with controlled small steps, 8 runs each, against BDPT (8 runs of 32 spp), 16 x 16
 * blocks and the image mean, alpha = 0.01 Sidak over the blocks, the mean and the 4 methods. */
static const struct {
    const char *name;
    enum mlt_method m;
    enum small_step step;
} chain_cfg[] = {{"pssmlt", MLT_PSSMLT, SMALL_STEP_PSS},
                 {"mmlt", MLT_MMLT, SMALL_STEP_PSS},
                 {"pitp", MLT_PITP, SMALL_STEP_PSS},
                 {"mmlt controlled", MLT_MMLT, SMALL_STEP_CONTROLLED}};

/* One method per test, so that --jobs spreads them; the BDPT reference is rendered once
 * (support/disk_cache.h). */
ParameterizedTestParameters(stat_thinlens, markov_chain_methods_agree_with_bdpt)
{
    static int idx[] = {0, 1, 2, 3};
    return cr_make_param_array(int, idx, 4);
}
ParameterizedTest(int *param, stat_thinlens, markov_chain_methods_agree_with_bdpt, .timeout = 600)
{
    struct scene *sc = test_scene(SCENE);
    struct stack ref, a;
    struct run b = {sc, {.method = METHOD_BDPT, .spp = 32, .threads = 2, .max_length = 4}};
    stack_runs_cached(&ref, render_run, &b, 8, 700, 16, sc, "bdpt spp 32 threads 2 max_length 4");
    const int i = *param;
    struct chain_run c = {sc, chain_cfg[i].m, chain_cfg[i].step};
    stack_runs(&a, chain_render, &c, 8, 800 + 20 * (uint64_t)i, 16);
    double pm, worst;
    int f = stack_compare(&a, &ref, 4, &pm, &worst);
    fprintf(stderr, "thinlens %s: %g +- %g vs BDPT %g +- %g: %d failing (mean p %.3g, worst block p %.3g)\n",
            chain_cfg[i].name, a.mean, a.mean_se, ref.mean, ref.mean_se, f, pm, worst);
    cr_assert_eq(f, 0, "%s: %d comparisons fail", chain_cfg[i].name, f);
    scene_free(sc);
}
