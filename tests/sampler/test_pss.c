/* The primary-sample-space state: exact restore on reject, and a Metropolis chain driven by it
 * reproduces a known 2D target with every option (Kelemen, Gaussian, rap, cdc). */
#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>

#include "base/vecmath.h"
#include "sampler/pss.h"
#include "support/chi2.h"
#include <math.h>
#include <string.h>

static void read_dims(struct pss_sampler *p, double *out, int n)
{
    sampler_begin(&p->base, STREAM_CAMERA, 0);
    out[0] = sampler_next(&p->base, DIM_IMAGE_X);
    out[1] = sampler_next(&p->base, DIM_IMAGE_Y);
    for (int v = 1; v < n; v++) {
        sampler_begin(&p->base, STREAM_CAMERA, v);
        out[2 * v] = sampler_next(&p->base, DIM_DISCRETE);
        out[2 * v + 1] = sampler_next(&p->base, DIM_CONTINUOUS);
    }
}

Test(pss, reject_restores_bit_for_bit)
{
    static struct pss_sampler p;
    struct pss_opts o;
    pss_opts_default(&o, 320, 180);
    pss_init(&p, &o, 1, 0);
    double a[16], b[16], c[16];
    read_dims(&p, a, 4);
    for (int i = 0; i < 100; i++) {
        bool large = i % 7 == 0;
        pss_begin(&p, large);
        read_dims(&p, b, 3 + i % 4); /* sometimes more dims than before, sometimes fewer */
        pss_reject(&p);
        pss_begin(&p, false);
        pss_reject(&p);
        static double u1[STREAM_COUNT][STREAM_DIMS], u2[STREAM_COUNT][STREAM_DIMS];
        pss_export(&p, u1);
        pss_begin(&p, false);
        read_dims(&p, c, 4);
        pss_reject(&p);
        pss_export(&p, u2);
        cr_assert(memcmp(u1, u2, sizeof u1) == 0, "reject did not restore the state (iteration %d)", i);
        pss_begin(&p, false);
        read_dims(&p, c, 4);
        pss_accept(&p);
    }
    (void)a;
}

/* Kelemen's kernel: log(|step| / s2) / log(s1 / s2) is uniform on [0, 1) and the sign is fair.
 * 1M steps in 2 x 1024 cells (488 expected each), alpha = 0.01 Sidak-corrected like every chi2 case.
 * Fine cells catch a table-only kernel (8 bits of xi: 3 of 4 cells empty). */
Test(pss, kelemen_step_distribution)
{
    enum { N = 1000000, B = 1024 };
    static struct pss_sampler p;
    static double count[2][B];
    struct pss_opts o;
    pss_opts_default(&o, 320, 180);
    pss_init(&p, &o, 5, 0);
    double lr = log(o.s1 / o.s2);
    for (int i = 0; i < N; i++) {
        double step = pss_small_step(&p, DIM_CONTINUOUS, 0.25) - 0.25;
        double xi = log(fabs(step) / o.s2) / lr;
        cr_assert(xi > -1e-9 && xi < 1 + 1e-9, "step %g outside [s1, s2]", step);
        int b = (int)(xi * B);
        count[step > 0][b < 0 ? 0 : b >= B ? B - 1 : b]++;
    }
    double chi2 = 0, e = (double)N / (2 * B);
    for (int s = 0; s < 2; s++)
        for (int b = 0; b < B; b++)
            chi2 += sqr(count[s][b] - e) / e;
    double pv = gsl_cdf_chisq_Q(chi2, 2 * B - 1);
    cr_assert(pv > chi2_alpha_sidak(), "Kelemen steps: chi2 %g, p %g", chi2, pv);
}

Test(pss, small_steps_respect_annotations)
{
    static struct pss_sampler p;
    struct pss_opts o;
    pss_opts_default(&o, 1600, 900);
    o.cdc = true;
    o.rap = true;
    pss_init(&p, &o, 2, 0);
    double sx = 0, sy = 0;
    for (int i = 0; i < 200000; i++) {
        cr_assert_eq(pss_small_step(&p, DIM_DISCRETE, 0.3), 0.3);
        double dx = pss_small_step(&p, DIM_IMAGE_X, 0.5) - 0.5, dy = pss_small_step(&p, DIM_IMAGE_Y, 0.5) - 0.5;
        sx += fabs(dx);
        sy += fabs(dy);
    }
    /* isotropic in pixels: mean |dx| * W == mean |dy| * H (1 % tolerance, 200k draws each) */
    cr_assert(fabs(sx * 1600 / (sy * 900) - 1) < 0.01, "pixel step ratio %g", sx * 1600 / (sy * 900));
}

/* A known target on [0,1]^2 over one image dim and one discrete dim (so rap and cdc act). */
static double target(double x, double y) { return (x + 0.5) * (sin(2 * M_PI * y) + 1.5); }
static double target_cell(int i, int j, int n)
{
    double x0 = (double)i / n, x1 = (double)(i + 1) / n, y0 = (double)j / n, y1 = (double)(j + 1) / n;
    double ix = 0.5 * (x1 * x1 - x0 * x0) + 0.5 * (x1 - x0);
    double iy = -(cos(2 * M_PI * y1) - cos(2 * M_PI * y0)) / (2 * M_PI) + 1.5 * (y1 - y0);
    return ix * iy / 1.5; /* total integral: 1 * 1.5 */
}

/* 4000 independent chains of 1000 steps (p_large 0.1) from uniform starts; the final states are
 * binned on 8x8 cells and compared with the target by chi-square. power < 1 tempers the acceptance
 * ratio, a broken chain the test must reject. */
static double chain_pvalue(const struct pss_opts *o, double power, uint64_t seed)
{
    enum { N = 4000, STEPS = 1000, G = 8 };
    static struct pss_sampler p;
    double count[G][G] = {{0}};
    rng r;
    rng_seed(&r, seed, 99);
    for (int c = 0; c < N; c++) {
        pss_init(&p, o, seed, (uint64_t)c);
        sampler_begin(&p.base, STREAM_CAMERA, 0);
        double x = sampler_next(&p.base, DIM_IMAGE_X), y = sampler_next(&p.base, DIM_DISCRETE);
        double fx = target(x, y);
        for (int s = 0; s < STEPS; s++) {
            pss_begin(&p, rng_uniform(&r) < 0.1);
            sampler_begin(&p.base, STREAM_CAMERA, 0);
            double nx = sampler_next(&p.base, DIM_IMAGE_X), ny = sampler_next(&p.base, DIM_DISCRETE);
            double fy = target(nx, ny);
            if (rng_uniform(&r) < pow(fy / fx, power)) {
                pss_accept(&p);
                x = nx, y = ny, fx = fy;
            } else {
                pss_reject(&p);
            }
        }
        count[(int)(x * G)][(int)(y * G)]++;
    }
    double chi = 0;
    for (int i = 0; i < G; i++)
        for (int j = 0; j < G; j++) {
            double e = N * target_cell(i, j, G);
            chi += sqr(count[i][j] - e) / e;
        }
    return gsl_cdf_chisq_Q(chi, G * G - 1);
}

/* alpha = 0.01, Sidak over the 4 configurations below. */
Test(stat_pss, chain_reproduces_known_target)
{
    double alpha = 1 - pow(0.99, 1.0 / 4);
    struct pss_opts o;
    pss_opts_default(&o, 1600, 900);
    for (int cfg = 0; cfg < 4; cfg++) {
        struct pss_opts c = o;
        c.kernel = cfg == 1 ? KERNEL_GAUSSIAN : KERNEL_KELEMEN;
        c.rap = cfg >= 2;
        c.cdc = cfg == 3;
        double pv = chain_pvalue(&c, 1.0, 10 + cfg);
        cr_assert(pv > alpha, "config %d: p = %g", cfg, pv);
    }
}

/* The failure demonstration: accepting with (f(y)/f(x))^0.5 samples sqrt(f), which must fail. */
Test(stat_pss, tempered_chain_is_rejected)
{
    struct pss_opts o;
    pss_opts_default(&o, 1600, 900);
    double pv = chain_pvalue(&o, 0.5, 20);
    cr_assert(pv < 1e-4, "a chain targeting sqrt(f) passed: p = %g", pv);
}
