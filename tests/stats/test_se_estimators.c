/* Which standard error of an MCMC mean to trust: the batch means of core/stats/mlt_stats.h (the
 * project's rule: batches of STATS_BATCH = 2048 values, complete ones only, sd of the batch means
 * over sqrt(batches); what PREFIX.csv's `stderr` and fig6.1's `stderr` are) or the ESS-based one
 * (the chain's sd times sqrt(1 / ESS), ESS by Geyer as core/stats/chain_ess.h), against the exact
 * standard error of the mean of a stationary AR(1) chain x_i = rho x_{i-1} + e_i (e_i unit
 * normal): Var(mean) = s2 / n (tau - 2 rho (1 - rho^n) / (n (1 - rho)^2)), s2 = 1 / (1 - rho^2),
 * tau = (1 + rho) / (1 - rho).
 *
 * 200 chains per case (rho 0.9 and 0.99, n 10^5 and 10^4), fixed seeds. Measured (mean of the 200
 * estimates against the truth, z = difference over the mean's standard error):
 *   rho 0.9,  n 1e5: batch +0.3 % (z +0.4, sd of one estimate 11 %), ESS +0.2 % (z +1.0, sd 2.4 %)
 *   rho 0.9,  n 1e4: batch +5.1 % (z +1.8, sd 41 %),                 ESS +0.9 % (z +1.7, sd 7.6 %)
 *   rho 0.99, n 1e5: batch -1.6 % (z -2.4, sd 9.7 %),                ESS +0.5 % (z +1.1, sd 6.7 %)
 *   rho 0.99, n 1e4: batch +2.3 % (z +0.8, sd 42 %),                 ESS -2.5 % (z -2.2, sd 16 %)
 * Both are about unbiased on average; one run's ESS-based error is more accurate (its
 * root mean square error against the truth is 1.5 to 5.4 times smaller). Batch means of n = 10^4 rest on 4
 * batches of 2048 (the last 1808 values dropped), hence their scatter.
 * The test: in every case the ESS-based mean within z = 3.23 of the truth (alpha 0.01 two-sided,
 * Bonferroni over the 4 cases) and within 5 %, and its root mean square error under the batch
 * means'. An ESS-based error that ignores the autocorrelation (sd / sqrt(n)) misses the truth by
 * sqrt(tau), 4.4 and 14 times, and fails. */
#include <criterion/criterion.h>

#include "base/rng.h"
#include "stats/chain_ess.h"
#include "stats/mlt_stats.h"
#include <math.h>
#include <stdlib.h>

static double gauss(rng *r)
{
    double u = rng_uniform(r), v = rng_uniform(r);
    return sqrt(-2 * log(1 - u)) * cos(2 * M_PI * v);
}

static double true_se(double rho, size_t n)
{
    double s2 = 1 / (1 - rho * rho), tau = (1 + rho) / (1 - rho);
    return sqrt(s2 / n * (tau - 2 * rho * (1 - pow(rho, (double)n)) / ((double)n * (1 - rho) * (1 - rho))));
}

/* Over `reps` chains of n draws: the mean and sd of each estimator's standard error (batch means
 * [0], ESS [1]) and their root mean square errors against the truth t. */
static void replicate(double rho, size_t n, int reps, uint64_t seed, double t, double mean[2], double sd[2],
                      double rmse[2])
{
    double *x = malloc(n * sizeof *x), s1[2] = {0}, s2[2] = {0}, d2[2] = {0};
    rng r;
    rng_seed(&r, seed, 5);
    for (int k = 0; k < reps; k++) {
        struct accept_cell c = {0};
        double v = gauss(&r) / sqrt(1 - rho * rho);
        for (size_t i = 0; i < n; i++) {
            v = rho * v + gauss(&r);
            x[i] = v;
            cell_add(&c, v);
        }
        double se[2] = {cell_stderr(&c), ess_se(x, 1, n)};
        for (int e = 0; e < 2; e++) {
            s1[e] += se[e];
            s2[e] += se[e] * se[e];
            d2[e] += (se[e] - t) * (se[e] - t);
        }
    }
    for (int e = 0; e < 2; e++) {
        mean[e] = s1[e] / reps;
        sd[e] = sqrt(fmax(0, (s2[e] - reps * mean[e] * mean[e]) / (reps - 1)));
        rmse[e] = sqrt(d2[e] / reps);
    }
    free(x);
}

Test(stat_se, batch_means_against_ess_on_ar1, .timeout = 600)
{
    const struct {
        double rho;
        size_t n;
    } cases[] = {{0.9, 100000}, {0.9, 10000}, {0.99, 100000}, {0.99, 10000}};
    enum { REPS = 200 };
    for (int i = 0; i < 4; i++) {
        double mean[2], sd[2], rmse[2], t = true_se(cases[i].rho, cases[i].n);
        replicate(cases[i].rho, cases[i].n, REPS, 100 + (uint64_t)i, t, mean, sd, rmse);
        double z = (mean[1] - t) / (sd[1] / sqrt(REPS));
        cr_assert(fabs(z) < 3.23 && fabs(mean[1] / t - 1) < 0.05,
                  "rho %g, n %zu: ESS-based se %g (z %+.2f) against the true %g", cases[i].rho, cases[i].n, mean[1], z,
                  t);
        cr_assert(rmse[1] < rmse[0], "rho %g, n %zu: rms error ESS %g, batch means %g", cases[i].rho, cases[i].n,
                  rmse[1], rmse[0]);
    }
}
