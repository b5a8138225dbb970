/* A claim's verdict from a measurement over seeds: "holds" when z >= 2 in the claimed direction
 * against every other method, "contradicted" when z <= -2 against one of them, "undecided"
 * otherwise, with the number of seeds the observed effect would need to decide it. The verdicts of
 * every figure's claims come from here, never from text typed by hand. */
#ifndef VERDICT_H
#define VERDICT_H

#include <stdbool.h>

#define VERDICT_Z 2.0

struct verdict {
    const char *word;   /* "holds", "contradicted" or "undecided" */
    double zmin;        /* the smallest z over the other methods, in the claimed direction */
    int deciding;       /* the other method of that z (index into the arrays), -1 if none */
    long seeds_needed;  /* undecided: seeds per method for |zmin| to reach 2 at the observed effect and
                         * spread (z grows as the square root of the seeds); 0 when decided, -1 when
                         * the observed effect is 0 */
};

/* Claim: method m has the largest (sign = +1) or smallest (sign = -1) mean among the k methods with
 * have[i] true. z[i] = sign (mean[m] - mean[i]) / sqrt(se[m]^2 + se[i]^2) is written for every
 * other method (nan for m itself and absent ones); seeds is the count behind the standard errors. */
struct verdict verdict_extreme(const double *mean, const double *se, const bool *have, int k, int m, int sign, int seeds,
                               double *z);

#endif
