/* Shared analysis of the chapter-6 tools: mean and standard error over seeds, per-block relative MSE
 * and its spread (the "uniformity" of an image's error), the log-log slope of error vs time. */
#ifndef CH6_STATS_H
#define CH6_STATS_H

#include "io/image.h"

/* Mean and standard error of the mean of x[0..n-1] (se = nan for n < 2). */
void ch6_mean_se(const double *x, int n, double *mean, double *se);
/* relMSE of a against ref over blk x blk blocks (partial blocks at the right and bottom edges are
 * dropped); writes up to cap values to out and returns the number of blocks. eps as img_relmse. */
int ch6_block_relmse(const struct image *a, const struct image *ref, int blk, double eps, double *out, int cap);
/* Spread of the block errors: the coefficient of variation (sample standard deviation / mean) of the
 * values; 0 for uniform error, nan for n < 2 or a zero mean. */
double ch6_spread(const double *v, int n);
/* Least-squares slope of log y against log x over the points with x, y > 0 (nan with fewer than 2). */
double ch6_loglog_slope(const double *x, const double *y, int n);

#endif
