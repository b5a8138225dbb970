/* Piecewise-constant distributions over [0,1) and [0,1)^2 with pdf and exact inverse
 * (thesis §5.1.1: sample = inverse CDF, so invert = CDF).
 *
 * A CDF array of n outcomes has n + 1 entries, cdf[0] = 0 and cdf[n] = 1 exactly. Outcome i owns
 * the half-open interval [cdf[i], cdf[i+1]); zero-weight outcomes own empty intervals and are
 * never chosen. Used both for discrete choices (light, triangle: one DIM_DISCRETE number, inverted
 * with invert_discrete) and for continuous piecewise-constant densities (environment map: the
 * remainder inside the chosen interval is reused, which keeps the map bijective). */
#ifndef DISTRIB_H
#define DISTRIB_H

#include <stdbool.h>

/* Fills cdf[0..n] from non-negative weights w[0..n-1]; returns the total, or 0 (and a uniform
 * CDF) when the total is zero, negative or non-finite. */
double cdf_build(double *cdf, const double *w, int n);
/* The outcome whose interval contains u (u in [0,1)): the largest i < n with cdf[i] <= u. */
int cdf_find(const double *cdf, int n, double u);
/* Sample continuously: outcome i and the position frac in [0,1) inside its interval. */
int cdf_sample_cont(const double *cdf, int n, double u, double *frac);
/* Inverse of cdf_sample_cont. */
double cdf_invert_cont(const double *cdf, int i, double frac);

/* 2D piecewise-constant density on [0,1)^2 over an nx x ny grid, w[y * nx + x]; sampled as a
 * marginal over rows (u1) then a conditional over columns (u2). */
struct distrib2d {
    int nx, ny;
    double total; /* sum of weights; 0 = unusable */
    double *marg; /* ny + 1 */
    double *cond; /* ny * (nx + 1) */
};
bool distrib2d_init(struct distrib2d *d, const double *w, int nx, int ny);
void distrib2d_free(struct distrib2d *d);
/* (u1, u2) -> point (x, y) in [0,1)^2 with density *pdf (w.r.t. dx dy). */
void distrib2d_sample(const struct distrib2d *d, double u1, double u2, double *x, double *y, double *pdf);
double distrib2d_pdf(const struct distrib2d *d, double x, double y);
/* Exact inverse; false where the density is zero. */
bool distrib2d_invert(const struct distrib2d *d, double x, double y, double *u1, double *u2);

#endif
