/* Verdicts from z values (verdict.h). */
#include <math.h>
#include <stdbool.h>

#include "common/verdict.h"

struct verdict verdict_extreme(const double *mean, const double *se, const bool *have, int k, int m, int sign, int seeds,
                               double *z)
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
    if (v.zmin >= VERDICT_Z) v.word = "holds";
    else if (v.zmin <= -VERDICT_Z) v.word = "contradicted";
    else if (v.zmin == 0 || !isfinite(v.zmin)) v.seeds_needed = -1;
    else {
        double r = VERDICT_Z / fabs(v.zmin);
        v.seeds_needed = (long)ceil(seeds * r * r - 1e-9); /* 4 (2 / sqrt 0.5)^2 is 32, not 33 */
    }
    return v;
}
