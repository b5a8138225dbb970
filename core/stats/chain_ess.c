/* Multi-chain effective sample size by Geyer's initial monotone sequence (see chain_ess.h). */
#include "stats/chain_ess.h"
#include "base/util.h"
#include <gsl/gsl_fft_complex.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>

/* The biased autocovariances acov[0..n) of v by FFT; buf holds 2 * len doubles, len a power of two
 * >= 2n. */
static void autocov(const double *v, size_t n, double *acov, double *buf, size_t len)
{
    double mu = gsl_stats_mean(v, 1, n);
    for (size_t i = 0; i < len; i++) {
        buf[2 * i] = i < n ? v[i] - mu : 0;
        buf[2 * i + 1] = 0;
    }
    gsl_fft_complex_radix2_forward(buf, 1, len);
    for (size_t i = 0; i < len; i++) {
        buf[2 * i] = buf[2 * i] * buf[2 * i] + buf[2 * i + 1] * buf[2 * i + 1];
        buf[2 * i + 1] = 0;
    }
    gsl_fft_complex_radix2_inverse(buf, 1, len); /* divides by len */
    for (size_t t = 0; t < n; t++)
        acov[t] = buf[2 * t] / (double)n;
}

/* Geyer's initial monotone sequence over rho[0..n): -1 + 2 sum of the positive, non-increasing
 * pair sums. */
static double geyer_tau(const double *rho, size_t n)
{
    double sum = 0, prev = INFINITY;
    for (size_t t = 0; t + 1 < n; t += 2) {
        double p = rho[t] + rho[t + 1];
        if (!(p > 0)) break;
        if (p > prev) p = prev;
        sum += p;
        prev = p;
    }
    return -1 + 2 * sum;
}

double ess_tau(const double *x, int m, size_t n)
{
    if (n < 4 || m < 1) return NAN;
    size_t len = 1;
    while (len < 2 * n)
        len *= 2;
    double *buf = xmalloc(2 * len * sizeof *buf);
    double *acov = xmalloc(n * sizeof *acov), *mean_acov = xcalloc(n, sizeof *mean_acov);
    double W = 0, mean_sum = 0, mean_sq = 0;
    for (int c = 0; c < m; c++) {
        const double *v = x + (size_t)c * n;
        autocov(v, n, acov, buf, len);
        for (size_t t = 0; t < n; t++)
            mean_acov[t] += acov[t] / m;
        double mu = gsl_stats_mean(v, 1, n);
        W += acov[0] * (double)n / (double)(n - 1) / m; /* the chain's sample variance */
        mean_sum += mu;
        mean_sq += mu * mu;
    }
    double grand = mean_sum / m;
    double B = m > 1 ? (double)n * (mean_sq - m * grand * grand) / (m - 1) : 0;
    double var_plus = (double)(n - 1) / (double)n * W + (B > 0 ? B : 0) / (double)n;
    double tau = NAN;
    if (var_plus > 0) {
        for (size_t t = 0; t < n; t++)
            acov[t] = 1 - (W - mean_acov[t]) / var_plus; /* rho_t, in place */
        tau = geyer_tau(acov, n);
        /* Stan's bound for antithetic chains: ESS at most m n log10(m n) */
        double lo = 1 / log10((double)m * (double)n);
        if (tau < lo) tau = lo;
    }
    free(mean_acov);
    free(acov);
    free(buf);
    return tau;
}

double ess_of(const double *x, int m, size_t n) { return (double)m * (double)n / ess_tau(x, m, n); }

double ess_se(const double *x, int m, size_t n)
{
    size_t N = (size_t)m * n;
    double mean = 0, q = 0;
    for (size_t i = 0; i < N; i++)
        mean += x[i];
    mean /= (double)N;
    for (size_t i = 0; i < N; i++)
        q += (x[i] - mean) * (x[i] - mean);
    return sqrt(q / (double)(N - 1) / ess_of(x, m, n));
}
