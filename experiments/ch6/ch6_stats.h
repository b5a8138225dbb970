/* Shared analysis of the chapter-6 tools: the log-log slope of error against time. The image
 * statistics they report are the core's: per-block relative MSE, its spread (the "uniformity" of an
 * image's error), a firefly-robust relMSE (stats/error_stats.h), the share of the error that survives
 * a box blur and its correlation length (stats/noise_corr.h); the mean and standard error over seeds
 * are common/verdict.h's. */
#ifndef CH6_STATS_H
#define CH6_STATS_H

#include "common/verdict.h"
#include "io/image.h"
#include "stats/error_stats.h"
#include "stats/noise_corr.h"

/* Least-squares slope of log y against log x over the points with x, y > 0 (nan with fewer than 2). */
double ch6_loglog_slope(const double *x, const double *y, int n);

#endif
