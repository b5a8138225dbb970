/* Verdicts from z values (verdict.h). */
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdbool.h>

#include "common/verdict.h"

void mean_se(const double *x, int n, double *mean, double *se)
{
    double m = 0, v = 0;
    for (int i = 0; i < n; i++)
        m += x[i];
    m = n > 0 ? m / n : NAN;
    for (int i = 0; i < n; i++)
        v += (x[i] - m) * (x[i] - m);
    *mean = m;
    *se = n > 1 ? sqrt(v / (n - 1) / n) : NAN;
}

static long seeds_for(double z, int seeds)
{
    if (z == 0 || !isfinite(z)) return -1;
    double r = VERDICT_Z / fabs(z);
    return (long)ceil(seeds * r * r - 1e-9); /* 4 (2 / sqrt 0.5)^2 is 32, not 33 */
}

struct verdict verdict_similar(double a, double se_a, double b, double se_b, double margin, int seeds)
{
    struct verdict v = {"undecided", NAN, 1, 0};
    double d = a - b, m = margin * fabs(b), s = sqrt(se_a * se_a + se_b * se_b);
    if (!(s > 0)) {
        v.seeds_needed = -1;
        return v;
    }
    double inside = (m - fabs(d)) / s; /* the smaller of the two one-sided z values */
    v.zmin = inside;
    if (inside >= VERDICT_Z)
        v.word = "holds";
    else if (inside <= -VERDICT_Z)
        v.word = "contradicted";
    else
        v.seeds_needed = seeds_for(inside, seeds);
    return v;
}

struct verdict verdict_extreme(const double *mean, const double *se, const bool *have, int k, int m, int sign,
                               int seeds, double *z)
{
    struct verdict v = {"undecided", INFINITY, -1, 0};
    for (int i = 0; i < k; i++) {
        z[i] = NAN;
        if (i == m || !have[i]) continue;
        double d = sign * (mean[m] - mean[i]), s = sqrt(se[m] * se[m] + se[i] * se[i]);
        z[i] = s > 0 ? d / s : d > 0 ? INFINITY : d < 0 ? -INFINITY : 0;
        if (isnan(z[i])) z[i] = 0; /* no standard error (one seed): nothing is decided */
        if (z[i] < v.zmin) v.zmin = z[i], v.deciding = i;
    }
    if (v.deciding < 0) return v; /* no other method: nothing to compare */
    if (v.zmin >= VERDICT_Z)
        v.word = "holds";
    else if (v.zmin <= -VERDICT_Z)
        v.word = "contradicted";
    else
        v.seeds_needed = seeds_for(v.zmin, seeds);
    return v;
}

struct verdict verdict_pair(double a, double se_a, double b, double se_b, int sign, int seeds)
{
    double z[2];
    return verdict_extreme((const double[2]){a, b}, (const double[2]){se_a, se_b}, (const bool[2]){true, true}, 2, 0,
                           sign, seeds, z);
}

double ratio_se(double a, double se_a, double b, double se_b)
{
    return fabs(a / b) * sqrt(pow(se_a / a, 2) + pow(se_b / b, 2));
}

struct verdict verdict_no_rejection(double p_min, double alpha, int m)
{
    double each = -expm1(log1p(-alpha) / m);
    struct verdict v = {p_min >= each ? "holds" : "contradicted", 0, 0, 0};
    v.zmin = gsl_cdf_ugaussian_Qinv(each) - gsl_cdf_ugaussian_Qinv(fmin(fmax(p_min, 1e-300), 1 - 1e-12));
    return v;
}
