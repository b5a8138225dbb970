/* Effective sample size and integrated autocorrelation time of m chains of n draws (chain-major,
 * x[c * n + i]), as Vehtari et al. (2021) define the multi-chain ESS that Stan reports: per chain the
 * autocovariances (biased, over n, by FFT: zero-padded to a power of two at least 2n, so the
 * circular products are the linear ones), combined as rho_t = 1 - (W - mean over chains of acov_t)
 * / var+ (W and var+ as for R-hat, chain_rhat.h), and summed by Geyer's (1992) initial monotone
 * sequence estimator: the sums of adjacent pairs P_j = rho_2j + rho_2j+1 are kept while positive
 * and made non-increasing; tau = -1 + 2 sum_j P_j and ESS = m n / tau. With m = 1 this is the one
 * chain's ESS. A chain of independent draws has tau = 1; AR(1) with coefficient phi has
 * tau = (1 + phi) / (1 - phi). */
#ifndef CHAIN_ESS_H
#define CHAIN_ESS_H

#include <stddef.h>

/* tau in draws (at least 1 / log10(m n), Stan's bound; NaN when every draw is equal, or n < 4). */
double ess_tau(const double *x, int m, size_t n);
/* m n / tau (NaN as tau). */
double ess_of(const double *x, int m, size_t n);
/* The standard error of the mean of all m n draws: their sd times sqrt(1 / ESS) (NaN as tau). On
 * AR(1) chains it is closer to the truth, and far less scattered, than batch means of
 * core/stats/mlt_stats.h's 2048 values (tests/stats/test_se_estimators.c); it needs the draws. */
double ess_se(const double *x, int m, size_t n);

#endif
