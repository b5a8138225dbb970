/* A sample's contributions to the image: (raster position, colour) pairs. MCMC states keep their
 * splat list so that the current state can be splatted again with expected-value weights. */
#ifndef SPLAT_H
#define SPLAT_H

#include "base/util.h"
#include "base/vecmath.h"
#include "io/image.h"
#include "sampler/sampler.h"

#define MAX_SPLATS (MAX_PATH_LENGTH + 2)

struct splat {
    double px, py;
    rgb c;
};

struct splat_list {
    int n;
    struct splat s[MAX_SPLATS];
};

/* A sample holds at most one camera-pixel sum and one t = 1 splat per path length: K + 1. */
static inline void splat_push(struct splat_list *l, double px, double py, rgb c)
{
    ASSERT(l->n < MAX_SPLATS); /* a dropped splat would bias the image silently */
    l->s[l->n++] = (struct splat){px, py, c};
}

/* Contributions dropped because they were NaN or infinite, by path length in segments. len[0]
 * holds what belongs to no single length: a sum over lengths (PT's and BDPT's camera-pixel sum, a
 * PSSMLT state re-splatted with its weight) that came out non-finite from finite terms. */
struct nonfinite {
    long len[MAX_PATH_LENGTH + 1];
};

static inline long nonfinite_total(const struct nonfinite *n)
{
    long t = 0;
    for (int k = 0; k <= MAX_PATH_LENGTH; k++)
        t += n->len[k];
    return t;
}

static inline void nonfinite_add(struct nonfinite *dst, const struct nonfinite *src)
{
    for (int k = 0; k <= MAX_PATH_LENGTH; k++)
        dst->len[k] += src->len[k];
}

/* Tests only: n > 0 makes every n-th non-zero contribution a thread computes (connect_st, the path
 * tracer's terms) non-finite in one channel, alternately NaN and +Inf, so that a test can see the
 * guards catch what no committed scene produces. bin/render sets it from PSS_INJECT_NONFINITE at
 * start; 0 otherwise, which costs one predictable branch per contribution. */
extern long nonfinite_inject_every;
rgb nonfinite_injected(rgb v);
static inline rgb nonfinite_inject(rgb v)
{
    return __builtin_expect(nonfinite_inject_every > 0, 0) ? nonfinite_injected(v) : v;
}

/* The one door to the image for every estimator: a NaN or infinite colour would poison the pixel
 * and, through the merge, the whole image's mean, so it is counted in *dropped instead. */
static inline void splat_finite(struct image *img, double px, double py, rgb c, long *dropped)
{
    if (vfinite(c))
        img_splat(img, px, py, c);
    else
        (*dropped)++;
}

/* Sum of the luminances: the scalar MCMC target of a splat list. */
static inline double splat_luminance(const struct splat_list *l)
{
    double s = 0;
    for (int i = 0; i < l->n; i++)
        s += luminance(l->s[i].c);
    return s;
}

#endif
