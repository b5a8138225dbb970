/* Rank-normalised split-R-hat (see chain_rhat.h). */
#include "stats/chain_rhat.h"
#include "base/util.h"
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void rank_normalise(const double *x, size_t N, double *z)
{
    size_t *p = xmalloc(N * sizeof *p);
    gsl_sort_index(p, x, 1, N);
    double *r = xmalloc(N * sizeof *r);
    for (size_t i = 0; i < N;) {
        size_t j = i;
        while (j + 1 < N && x[p[j + 1]] == x[p[i]])
            j++;
        double rank = 0.5 * (double)(i + j) + 1; /* ties share their average rank (1-based) */
        for (size_t q = i; q <= j; q++)
            r[p[q]] = rank;
        i = j + 1;
    }
    for (size_t i = 0; i < N; i++)
        z[i] = gsl_cdf_ugaussian_Pinv((r[i] - 0.375) / ((double)N + 0.25));
    free(r);
    free(p);
}

size_t split_chains(const double *x, int m, size_t n, double *out)
{
    size_t h = n / 2;
    for (int c = 0; c < m; c++) {
        const double *src = x + (size_t)c * n;
        memcpy(out + (size_t)(2 * c) * h, src, h * sizeof *out);
        memcpy(out + (size_t)(2 * c + 1) * h, src + (n - h), h * sizeof *out);
    }
    return h;
}

double rhat_basic(const double *x, int m, size_t n)
{
    double W = 0, mean_sum = 0, mean_sq = 0;
    for (int c = 0; c < m; c++) {
        const double *v = x + (size_t)c * n;
        double mu = gsl_stats_mean(v, 1, n);
        W += gsl_stats_variance_m(v, 1, n, mu);
        mean_sum += mu;
        mean_sq += mu * mu;
    }
    W /= m;
    double grand = mean_sum / m;
    double B = m > 1 ? (double)n * (mean_sq - m * grand * grand) / (m - 1) : 0;
    if (B < 0) B = 0; /* rounding of equal means */
    if (W == 0) return B > 0 ? INFINITY : NAN;
    double var_plus = (double)(n - 1) / (double)n * W + B / (double)n;
    return sqrt(var_plus / W);
}

double rhat_rank(const double *x, int m, size_t n)
{
    size_t N = (size_t)m * n;
    double *s = xmalloc(N * sizeof *s);
    size_t h = split_chains(x, m, n, s);
    size_t Ns = (size_t)(2 * m) * h;
    double *z = xmalloc(Ns * sizeof *z);
    rank_normalise(s, Ns, z);
    double bulk = rhat_basic(z, 2 * m, h);
    memcpy(z, s, Ns * sizeof *z);
    gsl_sort(z, 1, Ns);
    double med = gsl_stats_median_from_sorted_data(z, 1, Ns);
    for (size_t i = 0; i < Ns; i++)
        z[i] = fabs(s[i] - med);
    rank_normalise(z, Ns, z);
    double folded = rhat_basic(z, 2 * m, h);
    free(z);
    free(s);
    if (isnan(bulk) || isnan(folded)) return isnan(bulk) ? folded : bulk;
    return fmax(bulk, folded);
}
