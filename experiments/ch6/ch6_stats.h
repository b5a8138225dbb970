/* Shared analysis of the chapter-6 tools: mean and standard error over seeds, per-block relative MSE
 * and its spread (the "uniformity" of an image's error), the log-log slope of error vs time, and the
 * statistics that tell fireflies (error in single pixels) from splotches (error correlated over many
 * pixels): a firefly-robust relMSE, the share of the error that survives a box blur, and the error's
 * correlation length. */
#ifndef CH6_STATS_H
#define CH6_STATS_H

#include "common/verdict.h"
#include "io/image.h"
#include "stats/noise_corr.h" /* error_blur_share, the splotch statistic beside these */

/* relMSE of a against ref over blk x blk blocks (partial blocks at the right and bottom edges are
 * dropped); writes up to cap values to out and returns the number of blocks. eps as img_relmse. */
int ch6_block_relmse(const struct image *a, const struct image *ref, int blk, double eps, double *out, int cap);
/* Spread of the block errors: the coefficient of variation (sample standard deviation / mean) of the
 * values; 0 for uniform error, nan for n < 2 or a zero mean. */
double ch6_spread(const double *v, int n);
/* Least-squares slope of log y against log x over the points with x, y > 0 (nan with fewer than 2). */
double ch6_loglog_slope(const double *x, const double *y, int n);

/* The median of v[0..n-1] (reorders v; nan for n = 0). */
double ch6_median(double *v, int n);
/* relMSE of a against ref with the largest `drop` fraction of per-pixel errors (the sum over the
 * three channels) left out: the error without its fireflies. */
double ch6_trimmed_relmse(const struct image *a, const struct image *ref, double eps, double drop);
/* relMSE of a scaled to ref's mean luminance (as stats/noise_corr.h's error_blur_share scales it) against ref: the
 * error without the normalisation's part, which scales the whole image by one number. */
double ch6_relmse_scaled(const struct image *a, const struct image *ref, double eps);

#endif
