/* Statistical tests of the leaf BSDF families (thinsheet, diffuse_transmission, oren_nayar, phong).
 *  - chi-square (support/chi2.h) of sample() against pdf(): 1M samples per case, 32 x 64
 *    equal-area cells over the whole sphere (diffuse_transmission) or 128 x 64 cells of
 *    (cos theta, phi) over the upper hemisphere (oren_nayar, phong), alpha = 0.01 Sidak-corrected over CHI2_CASES;
 * failed samples go to the "other" cell, so the lobe choice and phong's lost below-horizon samples are tested too;
 * diffuse_transmission from both sides;
 *  - thinsheet: reflection frequency against R / (R + mean T), chi-square 1 dof, 1M samples, same
 *    alpha;
 *  - energy: Monte Carlo directional albedo with white albedo, 1M samples: <= 1 + 3 sigma; exactly 1
 *    (every weight 1) for diffuse_transmission and the non-absorbing sheet;
 *  - inversion: u' = invert(sample(u)) has the distribution of the u that sample() accepts (a
 *    two-sample chi-square of u against u' on 4 x 4 x 4 cells of the three numbers, 63 dof, or 10
 *    bins of the sheet's one number, 9 dof; 200k pairs per case, same alpha): the proportional lobe
 *    choice and the uniform point of the discrete interval make invert the exact conditional
 *    inverse (thesis Eq. 5.6-5.8). */
#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>

#include "sampler/sampler.h"
#include "support/chi2.h"
#include "support/leaf_util.h"
#include <stdio.h>

#define N_CHI2 1000000L
#define N_INV 200000L

struct dir_case {
    struct bsdf_ctx c;
    vec3 wi;
    struct sampler_rng s;
};

static bool case_sample(void *p, rng *r, vec3 *d)
{
    struct dir_case *k = p;
    sampler_rng_init(&k->s, r);
    sampler_begin(&k->s.base, STREAM_CAMERA, 0);
    struct bsdf_sample o;
    if (!bsdf_sample(&k->c, k->wi, &k->s.base, TRANSPORT_RADIANCE, &o) || o.delta) return false;
    *d = o.wo;
    return true;
}

static double case_pdf(void *p, vec3 d)
{
    struct dir_case *k = p;
    return bsdf_pdf(&k->c, k->wi, d);
}

/* Reflection-only families on the upper hemisphere, (u, v) = (cos theta, phi / 2 pi), density
 * 2 pi pdf: their pdf jumps to 0 at the horizon (oren_nayar's uniform part, phong's cut lobe), and
 * the sphere map puts the horizon on a cell edge where Simpson's rule sees both sides. 128 x 64
 * cells: phong's n = 200 peak (width ~0.005 in cos theta) spans several cells. */
static bool hemi_sample(void *p, rng *r, double *u, double *v)
{
    vec3 d;
    if (!case_sample(p, r, &d) || d.z <= 0) return false;
    *u = fmin(d.z, nextafter(1.0, 0.0));
    double phi = atan2(d.y, d.x) / (2 * M_PI);
    *v = phi < 0 ? phi + 1 : phi >= 1 ? 0 : phi;
    return true;
}

static double hemi_pdf(void *p, double u, double v)
{
    u = fmax(u, 1e-9); /* the horizon edge: the density's limit from above, where the samples are */
    double s = sqrt(fmax(0.0, 1 - u * u));
    return 2 * M_PI * case_pdf(p, v3(s * cos(2 * M_PI * v), s * sin(2 * M_PI * v), u));
}

static void chi2_material(const struct bsdf *b, const char *name, uint64_t seed)
{
    char buf[256];
    for (int side = 0; side < (b->transmissive ? 2 : 1); side++)
        for (int i = 0; i < LEAF_NWI; i++) {
            struct dir_case k = {bsdf_ctx_at(b, NULL), leaf_wi(i, side), {{0}, 0}};
            struct chi2_result r = b->transmissive
                                       ? chi2_test_dir(case_sample, case_pdf, &k, 32, 64, N_CHI2, seed + 10 * side + i)
                                       : chi2_test_2d(hemi_sample, hemi_pdf, &k, 128, 64, N_CHI2, seed + i);
            cr_log_info("%s side %d cos=%.2f: %s", name, side, leaf_wi_cos[i], chi2_describe(&r, buf, sizeof buf));
            cr_assert(r.pass, "%s side %d wi %d: %s", name, side, i, chi2_describe(&r, buf, sizeof buf));
            cr_assert(r.mass <= 1 + 1e-3, "%s: mass %g", name, r.mass);
        }
}

Test(stat_bsdf_leaf, chi2_diffuse_transmission)
{
    struct bsdf a = leaf_dt(0.5, v3s(1)), b = leaf_dt(0.8, v3(0.7, 0.8, 0.9));
    chi2_material(&a, "dt 0.5", 500);
    chi2_material(&b, "dt 0.8", 600);
}

Test(stat_bsdf_leaf, chi2_oren_nayar)
{
    struct bsdf a = leaf_on(1.0, v3s(1)), b = leaf_on(0.3, v3(0.7, 0.55, 0.3));
    chi2_material(&a, "oren_nayar 1", 700);
    chi2_material(&b, "oren_nayar 0.3", 800);
}

Test(stat_bsdf_leaf, chi2_phong)
{
    struct bsdf a = leaf_phong(10, 0.2, v3s(1)), b = leaf_phong(200, 0.2, v3s(1)), c = leaf_phong(40, 0.8, v3s(1));
    chi2_material(&a, "phong 10/0.2", 900);
    chi2_material(&b, "phong 200/0.2", 1000);
    chi2_material(&c, "phong 40/0.8", 1100);
}

/* The sheet's reflection frequency against P = R / (R + mean T), from both sides. */
Test(stat_bsdf_leaf, thinsheet_choice_frequencies)
{
    struct bsdf sh[2] = {leaf_sheet(1.5, 0.5, v3s(0)), leaf_sheet(1.5, 0.4, v3(0.2, 1.5, 3.0))};
    struct sampler_independent s;
    sampler_independent_init(&s, 17, 0);
    for (int m = 0; m < 2; m++)
        for (int side = 0; side < 2; side++)
            for (int i = 0; i < LEAF_NWI; i++) {
                vec3 wi = leaf_wi(i, side);
                struct bsdf_ctx c = bsdf_ctx_at(&sh[m], NULL);
                struct thinsheet_optics o = thinsheet_optics(&sh[m], fabs(wi.z));
                double P = o.R / (o.R + (o.T.x + o.T.y + o.T.z) / 3);
                long refl = 0;
                for (long n = 0; n < N_CHI2; n++) {
                    struct bsdf_sample b;
                    sampler_begin(&s.base, STREAM_CAMERA, 0);
                    cr_assert(bsdf_sample(&c, wi, &s.base, TRANSPORT_RADIANCE, &b));
                    refl += b.lobe == THINSHEET_LOBE_REFLECT;
                }
                double e = N_CHI2 * P, stat = sqr(refl - e) / (e * (1 - P)), p = gsl_cdf_chisq_Q(stat, 1);
                cr_log_info("thinsheet %d side %d cos=%.2f: P=%.5f observed %.5f p=%.3g", m, side, leaf_wi_cos[i], P,
                            (double)refl / N_CHI2, p);
                cr_assert(p > chi2_alpha_sidak(), "sheet %d side %d wi %d: P %g observed %g p %g", m, side, i, P,
                          (double)refl / N_CHI2, p);
            }
}

/* White furnace: the directional albedo (mean sample weight) of white materials. */
static void albedo_of(const struct bsdf *b, vec3 wi, double *mean, double *sigma, double *lo, double *hi)
{
    struct sampler_independent s;
    sampler_independent_init(&s, 23, b->type);
    struct bsdf_ctx c = bsdf_ctx_at(b, NULL);
    double sum = 0, sum2 = 0;
    *lo = INFINITY, *hi = 0;
    for (long n = 0; n < N_CHI2; n++) {
        struct bsdf_sample o;
        sampler_begin(&s.base, STREAM_CAMERA, 0);
        double y = bsdf_sample(&c, wi, &s.base, TRANSPORT_IMPORTANCE, &o) ? vmax(o.weight) : 0;
        sum += y;
        sum2 += y * y;
        *lo = fmin(*lo, y), *hi = fmax(*hi, y);
    }
    *mean = sum / N_CHI2;
    *sigma = sqrt(fmax(0, sum2 / N_CHI2 - *mean * *mean) / N_CHI2);
}

/* Tungsten's Oren-Nayar (the full model with its A^2 inter-reflection term) is not energy conserving
 * at white albedo: measured 1.0329 +- 0.0002 at roughness 0.3, cos theta_i = 0.05 (1M samples);
 * reproduced as Tungsten has it, so the bound here is that model's, not 1. */
#define ON_BOUND 1.04
Test(stat_bsdf_leaf, white_furnace)
{
    struct {
        struct bsdf b;
        const char *name;
        bool conserves; /* every sample weighs exactly 1 */
        double bound;
    } m[] = {
        {leaf_dt(0.5, v3s(1)), "dt 0.5", true, 1},
        {leaf_dt(0.8, v3s(1)), "dt 0.8", true, 1},
        {leaf_sheet(1.5, 0.5, v3s(0)), "sheet", true, 1},
        {leaf_sheet(1.5, 0.4, v3(0.2, 1.5, 3.0)), "tinted sheet", false, 1},
        {leaf_on(0.3, v3s(1)), "oren_nayar 0.3", false, ON_BOUND},
        {leaf_on(1.0, v3s(1)), "oren_nayar 1", false, ON_BOUND},
        {leaf_on(2.0, v3s(1)), "oren_nayar 2", false, ON_BOUND},
        {leaf_phong(10, 0.2, v3s(1)), "phong 10/0.2", false, 1},
        {leaf_phong(200, 0.2, v3s(1)), "phong 200/0.2", false, 1},
        {leaf_phong(40, 0.8, v3s(1)), "phong 40/0.8", false, 1},
        {leaf_phong(1, 0, v3s(1)), "phong 1/0", false, 1},
        {leaf_phong(0, 0, v3s(1)), "phong 0/0", false, 1},
    };
    for (size_t j = 0; j < sizeof m / sizeof m[0]; j++)
        for (int side = 0; side < (m[j].b.transmissive ? 2 : 1); side++)
            for (int i = 0; i < LEAF_NWI; i++) {
                double mean, sigma, lo, hi;
                albedo_of(&m[j].b, leaf_wi(i, side), &mean, &sigma, &lo, &hi);
                cr_log_info("furnace %s side %d cos=%.2f: albedo %.6f +- %.6f", m[j].name, side, leaf_wi_cos[i], mean,
                            sigma);
                fprintf(stderr, "furnace %-15s side %d cos %.2f: albedo %.6f +- %.6f\n", m[j].name, side,
                        leaf_wi_cos[i], mean, sigma);
                cr_assert(mean <= m[j].bound + 3 * sigma + 1e-12, "%s wi %d: albedo %g sigma %g", m[j].name, i, mean,
                          sigma);
                if (m[j].conserves)
                    cr_assert(fabs(lo - 1) < 1e-12 && fabs(hi - 1) < 1e-12, "%s: weights in [%.17g, %.17g]", m[j].name,
                              lo, hi);
            }
}

/* Two-sample chi-square of the accepted forward numbers u against u' = invert(sample(u)). */
static void inverse_distribution(const struct bsdf *b, vec3 wi, const char *name, int *tested)
{
    static struct sampler_writer w;
    sampler_writer_init(&w, 31, b->type);
    rng r;
    rng_seed(&r, 37, b->type);
    struct rec_sampler q;
    struct bsdf_ctx c = bsdf_ctx_at(b, NULL);
    enum { B3 = 4, NB = B3 * B3 * B3 };
    long hu[NB] = {0}, hv[NB] = {0};
    int nb = b->dims == 1 ? 10 : NB;
    for (long n = 0; n < N_INV; n++) {
        struct bsdf_sample o, back;
        int rc = leaf_roundtrip(&c, wi, &r, &q, &w, &o, &back);
        if (rc == 1) continue;
        cr_assert_eq(rc, 0, "%s: round trip %d", name, rc);
        const double *v = &w.u[STREAM_CAMERA][SAMPLER_BLOCK];
        int cu = 0, cv = 0;
        if (b->dims == 1) {
            cu = (int)(q.u[0] * 10), cv = (int)(v[0] * 10);
        } else {
            for (int d = 0; d < 3; d++) {
                cu = cu * B3 + (int)(q.u[d] * B3);
                cv = cv * B3 + (int)(v[d] * B3);
            }
        }
        cr_assert(cv >= 0 && cv < nb);
        hu[cu]++, hv[cv]++;
    }
    double stat = 0;
    int cells = 0;
    for (int k = 0; k < nb; k++)
        if (hu[k] + hv[k] > 0) {
            stat += sqr((double)hu[k] - hv[k]) / (hu[k] + hv[k]);
            cells++;
        }
    double p = gsl_cdf_chisq_Q(stat, cells - 1);
    cr_log_info("inverse %s wi.z=%.2f: chi2 %.1f dof %d p %.3g", name, wi.z, stat, cells - 1, p);
    cr_assert(p > chi2_alpha_sidak(), "%s wi.z %g: inverted numbers not distributed as u: chi2 %g p %g", name, wi.z,
              stat, p);
    (*tested)++;
}

Test(stat_bsdf_leaf, inverted_numbers_follow_the_forward_ones)
{
    struct {
        struct bsdf b;
        const char *name;
    } m[] = {
        {leaf_sheet(1.5, 0.4, v3(0.2, 1.5, 3.0)), "tinted sheet"},
        {leaf_dt(0.8, v3(0.7, 0.8, 0.9)), "dt 0.8"},
        {leaf_on(0.3, v3s(1)), "oren_nayar 0.3"},
        {leaf_on(1.0, v3s(1)), "oren_nayar 1"},
        {leaf_phong(10, 0.2, v3s(1)), "phong 10/0.2"},
        {leaf_phong(40, 0.8, v3s(1)), "phong 40/0.8"},
    };
    int tested = 0;
    for (size_t j = 0; j < sizeof m / sizeof m[0]; j++)
        for (int side = 0; side < (m[j].b.transmissive ? 2 : 1); side++)
            for (int i = 0; i < LEAF_NWI; i++)
                inverse_distribution(&m[j].b, leaf_wi(i, side), m[j].name, &tested);
    cr_assert_eq(tested, 4 * (2 + 2 + 1 + 1 + 1 + 1));
}
