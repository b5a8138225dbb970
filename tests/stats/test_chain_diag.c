/* The mixing diagnostics (core/stats/chain_rhat.h, chain_ess.h, chain_trace.h, mixing.h) on chains
 * with known answers: AR(1) chains of known integrated autocorrelation time, chains of equal and
 * of different distributions, a chain that never moves, a chain with a start-up transient. The
 * statistical ones use fixed seeds; each states its sample size and the spread its tolerance
 * stands on, measured over independent seeds. */
#include <criterion/criterion.h>

#include "base/rng.h"
#include "stats/chain_ess.h"
#include "stats/chain_rhat.h"
#include "stats/mixing.h"
#include <math.h>
#include <stdlib.h>

static double gauss(rng *r)
{
    double u = rng_uniform(r), v = rng_uniform(r);
    return sqrt(-2 * log(1 - u)) * cos(2 * M_PI * v);
}

/* m chains of n draws of x_i = phi x_{i-1} + e_i, started in the stationary distribution, plus
 * shift[c] for chain c (NULL: none). */
static double *ar1(int m, size_t n, double phi, const double *shift, uint64_t seed)
{
    double *x = malloc((size_t)m * n * sizeof *x);
    rng r;
    rng_seed(&r, seed, 3);
    for (int c = 0; c < m; c++) {
        double v = gauss(&r) / sqrt(1 - phi * phi);
        for (size_t i = 0; i < n; i++) {
            v = phi * v + gauss(&r);
            x[(size_t)c * n + i] = v + (shift ? shift[c] : 0);
        }
    }
    return x;
}

/* tau = (1 + phi) / (1 - phi) = 19 for phi = 0.9, ESS = m n / tau. 4 chains of 20 000 draws: over
 * 200 seeds the estimate's relative error had mean +1.1 % and sd 4.8 %; the tolerance is 15 %
 * (3 sd). An estimator summing the autocorrelations without Geyer's truncation, or one dropping
 * the factor 2, misses it by far more. */
Test(stat_chain_diag, ar1_tau_and_ess_by_geyer)
{
    enum { M = 4, N = 20000 };
    double phi = 0.9, tau = (1 + phi) / (1 - phi);
    double *x = ar1(M, N, phi, NULL, 11);
    double t = ess_tau(x, M, N), e = ess_of(x, M, N);
    cr_assert(fabs(t / tau - 1) < 0.15, "tau %g, expected %g", t, tau);
    cr_assert(fabs(e / (M * N / tau) - 1) < 0.15, "ESS %g, expected %g", e, M * N / tau);
    /* independent draws: tau 1 (same tolerance; the estimator's spread is smaller there) */
    double *w = ar1(M, N, 0, NULL, 12);
    cr_assert(fabs(ess_tau(w, M, N) - 1) < 0.15, "tau of white noise %g", ess_tau(w, M, N));
    free(w);
    free(x);
}

/* Through the recorder: 8 chains of 10^6 iterations of AR(1) with phi = 0.999 (tau = 1999) thinned
 * to 4096 values at most (stride 256), and the rows' tau in iterations. Over 20 seeds: mean
 * relative error -0.2 %, sd 3.8 %, largest 8.4 %; tolerance 15 % (4 sd). */
Test(stat_chain_diag, ar1_tau_through_thinned_traces)
{
    enum { M = 8 };
    long n = 1000000;
    double phi = 0.999, tau = (1 + phi) / (1 - phi);
    struct chain_trace *t = malloc(M * sizeof *t);
    rng r;
    rng_seed(&r, 21, 3);
    for (int c = 0; c < M; c++) {
        trace_init(&t[c], 0);
        double v = gauss(&r) / sqrt(1 - phi * phi);
        for (long i = 0; i < n; i++) {
            v = phi * v + gauss(&r);
            if (trace_step(&t[c], true)) trace_keep(&t[c], v, v);
        }
    }
    struct mixing_row rows[2];
    int nr = mixing_rows(t, M, rows, 2);
    cr_assert_eq(nr, 1);
    cr_assert_eq(rows[0].thin, 256);
    cr_assert(fabs(rows[0].tau / tau - 1) < 0.15, "tau %g, expected %g", rows[0].tau, tau);
    cr_assert_eq(rows[0].warn, 0, "healthy chains flagged: %u", rows[0].warn);
    free(t);
}

/* 4 chains of 1000 independent normal draws: R-hat below 1.01 (over 1000 seeds none reached it:
 * mean 1.0003). */
Test(stat_chain_diag, chains_of_one_distribution_give_rhat_below_1_01)
{
    double *x = ar1(4, 1000, 0, NULL, 31);
    double rh = rhat_rank(x, 4, 1000);
    cr_assert(rh < 1.01 && rh > 0.99, "R-hat %g", rh);
    free(x);
}

/* Two chains of 1000 draws, means 0 and 1 (unit variance): the pooled spread exceeds the chains'
 * own by about 1/4 of a variance, so R-hat is near sqrt(1.25) = 1.1; required above 1.05. Spreads
 * 1 and 3 with one mean: only the folded R-hat sees it. */
Test(stat_chain_diag, chains_of_different_distributions_give_large_rhat)
{
    double shift[] = {0, 1};
    double *x = ar1(2, 1000, 0, shift, 41);
    double rh = rhat_rank(x, 2, 1000);
    cr_assert(rh > 1.05, "R-hat %g", rh);
    for (size_t i = 1000; i < 2000; i++)
        x[i] = 3 * (x[i] - 1);
    double *z = malloc(2000 * sizeof *z), *s = malloc(2000 * sizeof *s);
    size_t h = split_chains(x, 2, 1000, s);
    rank_normalise(s, 4 * h, z);
    cr_assert(rhat_basic(z, 4, h) < 1.02, "bulk R-hat %g of equal locations", rhat_basic(z, 4, h));
    cr_assert(rhat_rank(x, 2, 1000) > 1.05, "folded R-hat missed the spread: %g", rhat_rank(x, 2, 1000));
    free(s);
    free(z);
    free(x);
}

/* A start-up transient: 4 AR(1) chains (phi = 0.9) of 100 000 iterations whose first 1 % sit 3
 * standard deviations high give a start-up z far beyond 4; without it |z| < 4 (z is standard
 * normal under no bias: P(|z| > 4) = 6e-5). */
Test(stat_chain_diag, startup_transient_gives_large_z)
{
    enum { M = 4 };
    long n = 100000;
    double phi = 0.9, sd = 1 / sqrt(1 - phi * phi);
    for (int biased = 0; biased < 2; biased++) {
        struct chain_trace t[M];
        double *x = ar1(M, (size_t)n, phi, NULL, 51);
        for (int c = 0; c < M; c++) {
            trace_init(&t[c], 0);
            for (long i = 0; i < n; i++)
                if (trace_step(&t[c], true)) {
                    double v = x[(size_t)c * n + i] + (biased && i < n / 100 ? 3 * sd : 0);
                    trace_keep(&t[c], v, v);
                }
        }
        struct mixing_row rows[1];
        int nr = mixing_rows(t, M, rows, 1);
        cr_assert_eq(nr, 1);
        if (biased)
            cr_assert(rows[0].startup_z > 4, "start-up z %g", rows[0].startup_z);
        else
            cr_assert(fabs(rows[0].startup_z) < 4, "start-up z %g without a transient", rows[0].startup_z);
        free(x);
    }
}
