/* What the chapter-4 figure tools (fig4_1, fig4_2, fig4_3) share: a Monte Carlo reference rendered
 * once and cached as EXR, a false-colour-free error image, claims rows over seeds (mean and standard
 * error: verdict.h's mean_se). */
#ifndef CH4_COMMON_H
#define CH4_COMMON_H

#include "common/claims.h"
#include "io/image.h"
#include "mc/render.h"
#include "scene/scene.h"
#include <stdint.h>
#include <stdio.h>

/* The metadata lines "# seeds S..S+N-1" and "# threads T" (csv_meta.h). */
void ch4_meta_runs(FILE *f, uint64_t seed, int seeds, int threads);

/* The scene rendered with `method` at `spp` (fixed seed 12345), cached as `path` by
 * common/refcache.h's rule: reused while the key beside it (the scene's content hash, the method,
 * samples, seed, longest path and size) is the current one, else rendered again. */
struct image *ch4_reference(const struct scene *sc, enum method method, int spp, const char *path, int threads,
                            const char *prog, char *err, size_t errlen);
/* DIR/NAME.exr and DIR/NAME.png. */
bool ch4_write_pair(const struct image *im, const char *dir, const char *name, char *err, size_t errlen);
/* A grey PNG of an error field: 0.5 + e / (2 range), clamped (range = 3 standard deviations unless
 * given > 0); returns the range used. */
bool ch4_write_error_png(const double *e, int w, int h, double *range, const char *path, char *err, size_t errlen);
/* Variance of a reference's pixel noise (luminance), from neighbouring-pixel differences:
 * mean((R(x+1,y) - R(x,y))^2) / 2, which the smooth image itself barely raises. */
double ch4_pixel_noise_var(const struct image *ref);
/* The most methods (configurations) a claim row compares. */
#define CH4_MAX_METHODS 16

/* A claims row (claims.h) for "method m has the largest (sign +1) or smallest (-1) mean" among the
 * n methods with have[]: x holds `seeds` per-run values per method (method i at x + i * seeds);
 * the verdict is verdict_extreme's over the seeds, the row lists every other method's mean and z. */
void ch4_claim_extreme(struct claims *cl, const char *id, const char *source, const char *claim, const char *stat,
                       const char *const *names, const double *x, int n, const bool *have, int m, int sign, int seeds);
/* The statistics row the figures share (fig4_1, fig4_2, fig4_3): one quantity of one configuration
 * over the seeds (the resolution column is fig4_2's only). */
struct ch4_stat_row {
    const char *config, *quantity;
    int resolution, seeds;
    double mean, se;
};
/* Fills row's mean and se from the seeds values at x (verdict.h's mean_se). */
void ch4_stat_row_of(struct ch4_stat_row *row, const double *x, int seeds);
/* A tool's claims table (claims_finish's Markdown) to stderr, freed; false when it is NULL (the
 * message is then in the tool's err). */
bool ch4_show_claims(char *md);
#endif
