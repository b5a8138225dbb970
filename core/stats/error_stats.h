/* An image's error against a reference, beyond its relMSE (io/image.h img_relmse): per block, where
 * it lies and how unevenly (the "uniformity" of the thesis's chapter 6), and the relMSE without the
 * parts a firefly or the normalisation carries. Every relative error is (a - r)^2 / (r^2 + eps) per
 * pixel and channel, as img_relmse's. */
#ifndef ERROR_STATS_H
#define ERROR_STATS_H

#include "io/image.h"

/* relMSE of a against ref over blk x blk blocks of the rectangle rect = {x, y, w, h} (partial blocks
 * at its right and bottom edges dropped) that lie wholly inside mask (a->w * a->h flags; NULL: every
 * block); writes up to cap values to out and returns the number of blocks. */
int block_relmse_in(const struct image *a, const struct image *ref, int blk, double eps, const int rect[4],
                    const bool *mask, double *out, int cap);
/* Whether the blk x blk block at (x0, y0) of a w-pixel-wide image lies wholly inside mask (NULL: yes). */
bool block_in_mask(const bool *mask, int w, int x0, int y0, int blk);
/* The same over the whole image. */
int block_relmse(const struct image *a, const struct image *ref, int blk, double eps, double *out, int cap);
/* The coefficient of variation (sample standard deviation / mean) of v[0..n-1]: 0 for uniform
 * error, nan for n < 2 or a zero mean. */
double block_spread(const double *v, int n);
/* The median of v[0..n-1] (reorders v; nan for n = 0). */
double median_of(double *v, int n);
/* relMSE of a against ref with the largest `drop` fraction of per-pixel errors (the sum over the
 * three channels) left out: the error without its fireflies. */
double trimmed_relmse(const struct image *a, const struct image *ref, double eps, double drop);
/* relMSE of a scaled to ref's mean luminance (stats/noise_corr.h mean_lum_scale) against ref: the
 * error without the normalisation's part, which scales the whole image by one number. */
double relmse_scaled(const struct image *a, const struct image *ref, double eps);
/* relMSE of a against ref over the pixels whose mask flag (a->w * a->h flags) equals `in`: the error
 * of one kind of region (the glossy surfaces, or the rest); nan when there is no such pixel. */
double relmse_where(const struct image *a, const struct image *ref, double eps, const bool *mask, bool in);

#endif
