/* Agreement of two estimators from independent replicate renders: per-block Welch t-tests on a
 * downsampled luminance image plus a test of the image mean, Sidak-corrected at alpha = 0.01. */
#ifndef AGREE_H
#define AGREE_H

#include "io/image.h"
#include "mcmc/mlt.h"
#include <stdint.h>

#define AGREE_MAX_REPS 16
#define AGREE_MAX_BLOCKS (64 * 64)

struct stack {
    int w, h, reps;
    double m[AGREE_MAX_BLOCKS], v[AGREE_MAX_BLOCKS]; /* block means and variances of the mean */
    double mean, mean_se;                            /* image mean luminance */
};

/* Renders `reps` replicates with seeds seed0, seed0 + 1, ... and accumulates their blk x blk blocks. */
typedef struct image *(*render_fn)(void *ctx, uint64_t seed);
void stack_runs(struct stack *out, render_fn render, void *ctx, int reps, uint64_t seed0, int blk);

/* Number of failing comparisons (blocks + image mean) at alpha = 0.01 Sidak-corrected over those
 * comparisons times `families` (the number of such comparisons in one test); *pmean and *worst
 * receive p-values. */
int stack_compare(const struct stack *a, const struct stack *b, int families, double *pmean, double *worst);

/* mlt_render, failing the current test with its message when it refuses or finds no light. */
void mlt_render_ok(const struct scene *sc, const struct mlt_opts *o, struct mlt_result *r);

/* A replicate of an MLT render for stack_runs: ctx is a struct mlt_ctx, rendered with its options
 * and the replicate's seed (asserting success and no non-finite contribution). */
struct mlt_ctx {
    const struct scene *sc;
    struct mlt_opts o;
};
struct image *render_mlt(void *ctx, uint64_t seed);

#endif
