/* A sample's contributions to the image: (raster position, colour) pairs. MCMC states keep their
 * splat list so that the current state can be splatted again with expected-value weights. */
#ifndef SPLAT_H
#define SPLAT_H

#include "base/util.h"
#include "base/vecmath.h"
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

/* Sum of the luminances: the scalar MCMC target of a splat list. */
static inline double splat_luminance(const struct splat_list *l)
{
    double s = 0;
    for (int i = 0; i < l->n; i++) s += luminance(l->s[i].c);
    return s;
}

#endif
