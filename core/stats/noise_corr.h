/* The shape of an image's noise: normalised autocorrelation profiles of an error field along the
 * two image axes, and correlation lengths read off them (thesis §4.1, Figures 4.1-4.2).
 * rho(d) = [sum over pairs at lag d of e(p) e(p + d) / pairs(d)] / [sum e^2 / N], e with its mean
 * removed. A correlation length is the lag at which a profile first falls below a level, linearly
 * interpolated between the two integer lags around the crossing.
 * An MCMC render's error has two parts: each splat's own (pixel-sized, white: it adds to rho(0)
 * only) and the correlation between the splats of one chain excursion, whose shape is what the
 * proposals set. corr_length_lag1 therefore reads the length off the profile normalised at lag 1:
 * the lag where rho(d) / rho(1) falls below 1/e. For noise made of white noise plus noise with the
 * Gaussian autocorrelation exp(-d^2 / (4 s^2)) (white noise blurred by a Gaussian of standard
 * deviation s), that is sqrt(1 + 4 s^2), whatever the white part's share. */
#ifndef NOISE_CORR_H
#define NOISE_CORR_H

#include "io/image.h"

/* rho_x[d], rho_y[d] for d = 0..maxlag (horizontal and vertical lags); f is w*h, row-major.
 * maxlag must be below w and h. Returns false when the field is constant (no variance). */
bool corr_profiles(const double *f, int w, int h, int maxlag, double *rho_x, double *rho_y);
/* The same over the pixels of mask (w*h flags; NULL: every pixel): the mean and variance over them,
 * and a lag's sum over the pairs with both ends in it; NAN at a lag no such pair has. False also
 * when the mask is empty. */
bool corr_profiles_in(const double *f, int w, int h, const bool *mask, int maxlag, double *rho_x, double *rho_y);
/* The first lag at which rho[0..n-1] falls below level, interpolated; n - 1 when it never does. */
double corr_length(const double *rho, int n, double level);
/* 1 + the first lag d >= 1 at which rho[d] / rho[1] falls below 1/e, interpolated (n >= 2); NAN when
 * rho[1] <= 0 (no correlated part to measure); d - 1 when rho[d] is NAN before that (a masked
 * profile whose pairs end there). */
double corr_length_lag1(const double *rho, int n);
/* The luminance error field of an MCMC render against a reference, after scaling the render to the
 * reference's mean: e = lum(s I - R), s = mean lum R / mean lum I. The scale removes the error of
 * the chain's normalisation (one number for the whole image, which would correlate every pair of
 * pixels); w*h values, caller frees. */
double *error_field(const struct image *img, const struct image *ref);
/* How far the error of a render spreads (the splotchiness of Figs. 5.6 and 6.2-6.7): corr_length_lag1
 * of the error field's x and y profiles (lags up to 32), averaged; 1 for white noise, about
 * sqrt(1 + 4 s^2) for noise blurred by a Gaussian of standard deviation s. An axis whose lag-1
 * correlation is not positive has no correlated part and counts as 1, the floor of the measure (a
 * render dominated by isolated fireflies gives that). NAN only when the error is constant (an
 * error-free render) or the image is under 3 pixels on a side. */
double error_corr_length(const struct image *img, const struct image *ref);
/* error_corr_length over the pixels of mask (corr_profiles_in; NULL: every pixel), the render
 * scaled by the whole image's mean_lum_scale. */
double error_corr_length_in(const struct image *img, const struct image *ref, const bool *mask);
/* That scale, s = mean lum ref / mean lum img (1 when img is black). */
double mean_lum_scale(const struct image *img, const struct image *ref);

/* The share of the relative error that survives a k x k box blur (the splotch statistic of
 * Figs. 5.6 and 6.2-6.7). The relative error per pixel and channel is (s a - ref) /
 * sqrt(ref^2 + eps), with a first scaled by s to ref's mean luminance, so that the normalisation's
 * one number (which survives every blur) is left out; the blur is the mean over non-overlapping
 * k x k blocks (partial blocks dropped). Returns
 * mean(block mean^2) / mean(error^2): 1 / k^2 in expectation for white noise, near 1 for error that
 * is constant over regions much larger than k. */
double error_blur_share(const struct image *a, const struct image *ref, double eps, int k);
/* error_blur_share over the k x k blocks of the rectangle rect = {x, y, w, h} of the images (partial
 * blocks at its right and bottom edges dropped) that lie wholly inside mask (a->w * a->h flags; NULL:
 * every block), a scaled by s: the whole image's mean_lum_scale, so that an error spread over the
 * whole rectangle is not scaled away. NAN when no block is left. */
double error_blur_share_in(const struct image *a, const struct image *ref, double eps, int k, const int rect[4],
                           const bool *mask, double s);

#endif
