/* Weighted discrete picks: one outcome of n chosen in proportion to its weight by one uniform
 * number. Two forms of the same choice: from the weights themselves (a linear scan, for the few
 * outcomes of a technique choice: MCTLS's trial, thesis Eq. 4.5; PITP's technique, Eq. 5.22-5.25),
 * and from their running sums (a binary search, for a pool of many: the chain start's resampling of
 * the seed pass, MMLT paper §4). */
#ifndef PICK_H
#define PICK_H

/* The outcome i of w[0..n-1] (weights >= 0, sum > 0) whose share of [0, 1) holds u: the first i
 * with w[0] + ... + w[i] > u * sum and w[i] > 0; rounding at the top end falls back to the last
 * outcome of non-zero weight. */
int pick_weighted(const double *w, int n, double u);

/* The same choice from the running sums cdf[i] = w[0] + ... + w[i] of n weights (cdf[n - 1] > 0, not
 * normalised): the first i with cdf[i] > u * cdf[n - 1], or n - 1. */
long pick_cdf(const double *cdf, long n, double u);

#endif
