/* The independence sampler's acceptance from independent draws (core/stats/indep_accept.h): exact
 * on hand-made draws (zeros, clusters whose inner pairs are left out, jackknife replicates), and
 * the identity E[min(1, w(y)/w(x))] = E[min(W1, W2)] / E[W] against a running chain. */
#include <criterion/criterion.h>

#include "base/rng.h"
#include "stats/indep_accept.h"
#include <math.h>
#include <stdlib.h>

static double accept_of(double *w, long *cl, long n, long clusters, int per, int groups, double *theta)
{
    struct weighted_draws d = {n, w, cl, clusters, per, groups};
    indep_accept(&d, theta);
    return theta[0];
}

/* Weights 1, 2, 4 and one zero: the three positive pairs' minima sum to 4 over C(4, 2) = 6 pairs,
 * E[W] = 7/4, so the acceptance is (4/6) / (7/4) = 8/21. Without the zero: (4/3) / (7/3) = 4/7. */
Test(indep_accept, zeros_count_in_the_pairs_and_the_mean)
{
    double w[] = {4, 1, 2}, theta[JACK_MAX_GROUPS + 1];
    long cl[] = {0, 1, 2};
    cr_assert_float_eq(accept_of(w, cl, 3, 4, 1, 2, theta), 8.0 / 21, 1e-12);
    double w2[] = {4, 1, 2};
    long cl2[] = {0, 1, 2};
    cr_assert_float_eq(accept_of(w2, cl2, 3, 3, 1, 3, theta), 4.0 / 7, 1e-12);
}

/* Clusters of two draws: {1, 3}, {2}, {} (six draws), listed out of order. Only the pairs across
 * clusters count: 15 pairs less 3 inside clusters = 12; the positive ones across give 1 + 2 = 3,
 * E[W] = 1. */
Test(indep_accept, pairs_inside_a_cluster_are_left_out)
{
    double w[] = {1, 2, 3}, theta[JACK_MAX_GROUPS + 1];
    long cl[] = {0, 1, 0};
    cr_assert_float_eq(accept_of(w, cl, 3, 3, 2, 3, theta), 0.25, 1e-12);
    /* leaving out group 0 (cluster 0) leaves {2} and {}: no positive pair, E[W] = 2/4: 0 */
    cr_assert_float_eq(theta[1], 0, 1e-12);
    /* leaving out group 2 (the empty cluster 2): 4 draws, 6 - 2 pairs, minima 1 + 2, E[W] = 6/4 */
    cr_assert_float_eq(theta[3], (3.0 / 4) / (6.0 / 4), 1e-12);
}

/* The mean over clusters and its replicates; the jackknife error of a mean is the usual one. */
Test(indep_accept, jackknife_of_a_mean_is_the_standard_error)
{
    enum { N = 64000, G = 16 };
    double *v = malloc(N * sizeof *v), theta[G + 1];
    rng r;
    rng_seed(&r, 7, 1);
    double s = 0, s2 = 0;
    for (long i = 0; i < N; i++) {
        v[i] = rng_uniform(&r) < 0.3;
        s += v[i], s2 += v[i] * v[i];
    }
    jack_mean(v, N, G, theta);
    double m = s / N, se = sqrt((s2 / N - m * m) / (N - 1));
    cr_assert_float_eq(theta[0], m, 1e-12);
    /* delete-a-group jackknife of a mean: exact for equal groups up to the n/(n-1) factor */
    cr_assert(fabs(jack_se(theta, G) / se - 1) < 0.4, "jackknife %g vs %g", jack_se(theta, G), se);
    free(v);
}

/* The identity itself: an independence Metropolis-Hastings chain with proposal W = exp(Z), Z
 * standard normal (target density proportional to w under q), runs 400 000 steps; its mean
 * acceptance (batch means over 100 batches) must match the prediction from 400 000 independent
 * draws (jackknife error). Two-sided z test at alpha = 1e-4 (|z| < 3.9); this seed gives |z| < 1. */
Test(indep_accept, predicts_a_running_chain)
{
    enum { N = 400000, B = 100 };
    rng r;
    rng_seed(&r, 11, 2);
    double *w = malloc(N * sizeof *w), theta[17];
    long *cl = malloc(N * sizeof *cl);
    for (long i = 0; i < N; i++) {
        double u1 = rng_uniform(&r), u2 = rng_uniform(&r);
        w[i] = exp(sqrt(-2 * log1p(-u1)) * cos(2 * M_PI * u2));
        cl[i] = i;
    }
    double pred = accept_of(w, cl, N, N, 1, 16, theta), pse = jack_se(theta, 16);
    /* the chain: x from the stationary law w q is reached quickly from a typical start */
    double x = 1, sum = 0, bsum = 0, bsum2 = 0, batch = 0;
    for (long i = 0; i < N; i++) {
        double u1 = rng_uniform(&r), u2 = rng_uniform(&r);
        double y = exp(sqrt(-2 * log1p(-u1)) * cos(2 * M_PI * u2));
        double a = fmin(1, y / x);
        if (rng_uniform(&r) < a) x = y;
        sum += a, batch += a;
        if ((i + 1) % (N / B) == 0) {
            double bm = batch / (N / B);
            bsum += bm, bsum2 += bm * bm, batch = 0;
        }
    }
    double cm = sum / N, cse = sqrt((bsum2 / B - (bsum / B) * (bsum / B)) / (B - 1));
    double z = (cm - pred) / sqrt(cse * cse + pse * pse);
    cr_assert(fabs(z) < 3.9, "chain %g +- %g, predicted %g +- %g (z = %.2f)", cm, cse, pred, pse, z);
    free(w);
    free(cl);
}
