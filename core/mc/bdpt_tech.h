/* BDPT's per-technique images of one path length k: for every technique t = 1..k+1 (t camera
 * vertices, s = k + 1 - t emitter vertices) the sum of its MIS-weighted contributions and of their
 * squares, so that each technique's image and its variance per pixel come from one run. Summed
 * over t, the images are the length-k part of the rendered image. The variances tell which
 * techniques carry the error (fireflies): a technique whose weight is too large where its density
 * is small shows there. They leave out the covariances between the techniques of one sample, so
 * their sum is not the image's variance. Exact per pixel under the box filter; under the tent filter a
 * pixel's square carries the filter weight, not its square: an upper bound.
 *
 * Per thread one accumulator (bdpt_tech_add after every sample); the render driver merges them in
 * thread order over the job (io/image_merge.h), so the result is reproducible like the image. */
#ifndef BDPT_TECH_H
#define BDPT_TECH_H

#include "io/image.h"
#include "mc/integrator.h"
#include <stdio.h>

struct bdpt_tech {
    int k, w, h;
    bool tent;
    /* [2][k + 1][h][w][3]: per technique t (index t - 1) the contributions' sum, then their squares' */
    double *sum;
};

struct bdpt_tech *bdpt_tech_create(int k, int w, int h, bool tent);
void bdpt_tech_free(struct bdpt_tech *a);
size_t bdpt_tech_bytes(const struct bdpt_tech *a);
/* The sample bdpt_splats last evaluated into w (its length-k techniques, w->tech). */
void bdpt_tech_add(struct bdpt_tech *a, const struct scratch *w);
void bdpt_tech_accumulate(struct bdpt_tech *dst, const struct bdpt_tech *src);

/* The variance of a pixel's estimate sum / n from one technique: unbiased from the sum and the
 * sum of squares of the N samples that could land there, N = n for t >= 2 (the pixel's own
 * samples), N = n x pixels for t = 1 (every sample's light-tracing splat can land anywhere). */
double bdpt_tech_var(double sum, double sq, long n, double N);
/* Per technique over n samples per pixel, against the whole image `full` (final units): the mean
 * luminance of its image; rel_var, the mean over pixels and channels of the variance of its pixel
 * estimate over (full^2 + 0.01), the unit of relMSE (image.h's img_relmse); and top1, the share of
 * rel_var in the technique's worst 1 % of pixels. */
struct bdpt_tech_row {
    int s, t;
    double mean, rel_var, top1;
};
void bdpt_tech_rows(const struct bdpt_tech *a, long n, const struct image *full, struct bdpt_tech_row *rows);

/* PREFIX.tech-tT.exr/.png per technique (final units; PNGs exposed alike, 0.5 / the mean luminance
 * of the length-k image) and PREFIX.tech.csv: `header`, then `technique,s,t,mean,rel_var,
 * rel_var_share,top1_share`. All written atomically. */
bool bdpt_tech_write(const struct bdpt_tech *a, long n, const struct image *full, const char *prefix,
                     const char *header, char *err, size_t errlen);

#endif
