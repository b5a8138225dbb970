/* The rank-normalised split-R-hat of Vehtari, Gelman, Simpson, Carpenter and Bürkner (2021,
 * "Rank-normalization, folding, and localization: an improved R-hat for assessing convergence of
 * MCMC"), as Stan reports it. Draws are m chains of n each, chain-major (x[c * n + i]).
 *
 * Each chain is split in half (a chain drifting within itself disagrees with its own halves); all
 * draws are replaced by their normal scores, z = Phi^-1((r - 3/8) / (N + 1/4)) of their rank r
 * among the N draws (ties: the average rank); R-hat is the classical potential scale reduction
 * sqrt(var+ / W) of those, W the mean within-chain variance and var+ = (n-1)/n W + B/n. The bulk
 * R-hat is that of the draws, the folded R-hat that of |x - median| (it sees chains that agree in
 * location and differ in spread); the reported R-hat is the larger. Near 1 when the chains sample
 * the same distribution; Stan's threshold is 1.01. */
#ifndef CHAIN_RHAT_H
#define CHAIN_RHAT_H

#include <stddef.h>

/* Normal scores of x[0..N) into z (z may be x). */
void rank_normalise(const double *x, size_t N, double *z);
/* The m chains of n draws as 2m half chains of n/2 (an odd n's middle draw left out) into out;
 * returns the half length. */
size_t split_chains(const double *x, int m, size_t n, double *out);
/* sqrt(var+ / W) of m chains of n draws as they are; NaN when every draw is equal, +inf when each
 * chain is constant but they differ. */
double rhat_basic(const double *x, int m, size_t n);
/* max(bulk, folded) rank-normalised split-R-hat of m chains of n >= 4 draws. */
double rhat_rank(const double *x, int m, size_t n);

#endif
