/* Per-pixel mixing of a Markov chain renderer: in every pixel, the chains' visits (runs of
 * consecutive iterations whose state splatted there) over their iterations that splatted there
 * (render's PREFIX.mixing.exr). 1/ratio is the mean number of iterations a chain stayed in the
 * pixel once it got there: 1 where every iteration moved on, low where chains sat (a stuck state,
 * or steps too small to leave the pixel); core/mcmc/docs/outputs.md says how to read it.
 *
 * A visit, not a distinct state: a new state in the same pixel is not a new visit. Counting states
 * would call a chain of tiny accepted steps perfectly mixed (each step is a new state), while it
 * splats one pixel for thousands of iterations; on the Cornell box (MMLT, sigma 1e-6 against the
 * default 1/64, 32x32, 1M mutations) states over splats averaged 0.9999 and 0.81 over the pixels
 * splatted, visits over splats orders of magnitude apart (tests/mcmc/test_pixel_mixing.c).
 *
 * Counted on the current state after each iteration, one splat per iteration: what a chain that sits
 * somewhere leaves in the image is its current state, splatted over and over (expected-value
 * splatting pays it 1 - a per iteration, splat_ev.c); the proposals are new by construction and
 * would read 1 everywhere. A position counts in the pixel that contains it, whatever the film's
 * filter. A state of several splats (PSSMLT) is in a new pixel when its first splat is.
 *
 * Per thread, merged over the threads like the image. Counting allocates nothing. Must never
 * include anything of core/mcmc. */
#ifndef PIXEL_MIXING_H
#define PIXEL_MIXING_H

#include "io/image.h"
#include <stdbool.h>

struct pixel_mixing {
    int w, h;
    long *n; /* 2 per pixel, row-major: iterations that splatted there, visits */
};

/* Zeroed counters for a w x h image. */
void pixmix_init(struct pixel_mixing *m, int w, int h);
void pixmix_free(struct pixel_mixing *m);
/* dst += src (same size). */
void pixmix_merge(struct pixel_mixing *dst, const struct pixel_mixing *src);
/* Visits over splats per pixel, grey; 0 where nothing splatted. */
struct image *pixmix_image(const struct pixel_mixing *m);

/* The cell of raster position (px, py): the pixel containing it, -1 outside the image (or NaN). */
static inline long pixmix_cell(const struct pixel_mixing *m, double px, double py)
{
    if (!(px >= 0 && py >= 0 && px < m->w && py < m->h)) return -1;
    return (long)py * m->w + (long)px;
}

/* One iteration's splat of a chain's state in cell (-1: none); fresh: the chain arrived there with
 * this iteration. The first splat a pixel gets is a visit in any case, so that a pixel with splats
 * never reads 0 (a resumed run's counters start at the resume, its chains do not). */
static inline void pixmix_add(struct pixel_mixing *m, long cell, bool fresh)
{
    if (cell < 0) return;
    long *c = m->n + 2 * cell;
    c[1] += fresh || c[0] == 0;
    c[0]++;
}

#endif
