/* The chi-square harness itself: accepts a correct sampler, rejects a subtly wrong one. */
#include <criterion/criterion.h>

#include "sampling/warp.h"
#include "support/chi2.h"

static bool cos_sample(void *ctx, rng *r, vec3 *d)
{
    double skew = *(double *)ctx;
    double u1 = rng_uniform(r), u2 = rng_uniform(r);
    *d = warp_cosine_hemisphere(pow(u1, 1.0 + skew), u2); /* skew != 0 distorts the radial law */
    return true;
}
static double cos_pdf(void *ctx, vec3 d)
{
    (void)ctx;
    return warp_cosine_hemisphere_pdf(d);
}

/* 1M samples, 32 x 64 cells, alpha 0.01 Sidak over CHI2_CASES. */
Test(stat_chi2, accepts_cosine_hemisphere)
{
    double skew = 0;
    struct chi2_result r = chi2_test_dir(cos_sample, cos_pdf, &skew, 32, 64, 1000000, 1);
    char buf[256];
    cr_assert(r.pass, "%s", chi2_describe(&r, buf, sizeof buf));
    cr_assert(fabs(r.mass - 1) < 1e-3);
}

/* The same harness must reject a 2% distortion of the radial law: the failure demonstration. */
Test(stat_chi2, rejects_distorted_cosine)
{
    double skew = 0.02;
    struct chi2_result r = chi2_test_dir(cos_sample, cos_pdf, &skew, 32, 64, 1000000, 1);
    cr_assert(!r.pass, "distorted sampler passed: p=%g", r.pvalue);
}
