/* A claim's verdict from a measurement over seeds: "holds" when z >= 2 in the claimed direction
 * against every other method, "contradicted" when z <= -2 against one of them, "undecided"
 * otherwise, with the number of seeds the observed effect would need to decide it. The verdicts of
 * every figure's claims come from here, never from text typed by hand. */
#ifndef VERDICT_H
#define VERDICT_H

#include <stdbool.h>

#define VERDICT_Z 2.0

struct verdict {
    const char *word;  /* "holds", "contradicted" or "undecided" */
    double zmin;       /* the smallest z over the other methods, in the claimed direction */
    int deciding;      /* the other method of that z (index into the arrays), -1 if none */
    long seeds_needed; /* undecided: seeds per method for |zmin| to reach 2 at the observed effect and
                        * spread (z grows as the square root of the seeds); 0 when decided, -1 when
                        * the observed effect is 0 */
};

/* Mean and standard error of the mean of x[0..n-1] over seeds (se = nan for n < 2). */
void mean_se(const double *x, int n, double *mean, double *se);

/* Claim: method m has the largest (sign = +1) or smallest (sign = -1) mean among the k methods with
 * have[i] true. z[i] = sign (mean[m] - mean[i]) / sqrt(se[m]^2 + se[i]^2) is written for every
 * other method (nan for m itself and absent ones); seeds is the count behind the standard errors. */
struct verdict verdict_extreme(const double *mean, const double *se, const bool *have, int k, int m, int sign,
                               int seeds, double *z);

/* Claim: a lies above (sign = +1) or below (sign = -1) b, z = sign (a - b) / sqrt(se_a^2 + se_b^2)
 * (zmin; deciding is 1): verdict_extreme of two. A fixed bound is a b with se_b = 0. */
struct verdict verdict_pair(double a, double se_a, double b, double se_b, int sign, int seeds);

/* The ratio a / b's first-order (delta-method) standard error, a and b independent. */
double ratio_se(double a, double se_a, double b, double se_b);

/* Claim: a and b are similar, |a - b| within margin * b (an equivalence test, two one-sided z tests
 * against the margin): "holds" when both z values reach 2 (the difference lies inside the margin),
 * "contradicted" when (|a - b| - margin b) / se reaches 2 (outside it), "undecided" otherwise. zmin
 * is the deciding one; seeds_needed as above. */
struct verdict verdict_similar(double a, double se_a, double b, double se_b, double margin, int seeds);

/* Claim: no test of a family rejects (goodness of fit), at family-wise level alpha with a Sidak
 * correction over m tests: "holds" when the smallest p-value p_min is at least the per-test level
 * 1 - (1 - alpha)^(1/m), "contradicted" when it is below (a test cannot be undecided). zmin is the
 * margin in normal quantiles, Qinv(alpha_each) - Qinv(p_min): positive when it holds, as the z of
 * the other verdicts; deciding and seeds_needed are 0. */
struct verdict verdict_no_rejection(double p_min, double alpha, int m);

#endif
