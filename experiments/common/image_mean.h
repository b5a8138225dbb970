/* The mean luminance of an image: the scale of its relMSE epsilon and of its PNG exposure. The
 * core has no such function (stats/noise_corr.c sums luminance only as a ratio of two images), so
 * the tools share this one; it belongs in core/io/image.h when the core next changes. */
#ifndef IMAGE_MEAN_H
#define IMAGE_MEAN_H

struct image;

/* Mean over pixels of luminance (Rec. 709 weights, base/vecmath.h), summed row by row. */
double img_mean_luminance(const struct image *im);

#endif
