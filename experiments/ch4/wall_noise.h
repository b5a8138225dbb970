/* One PSSMLT render of the diffuse wall (scenes/wall) and the shape of its noise, for thesis
 * Figures 4.1-4.2: correlation lengths of the error against a reference along both image axes,
 * relative MSE and small-step acceptance. */
#ifndef WALL_NOISE_H
#define WALL_NOISE_H

#include "io/image.h"
#include "mcmc/mlt.h"
#include "scene/scene.h"

struct wall_cfg {
    bool rap, rap_resolution;
    double p_large;
    double mpp; /* mutations per pixel */
    long seed_paths;
    int threads;
    int maxlag; /* profiles cover lags 0..maxlag */
};

struct wall_meas {
    double lx, ly;         /* correlation lengths (pixels): corr_length_lag1 of the x and y profiles */
    double rho1_x, rho1_y; /* the profiles at lag 1: the correlated part's share of the variance */
    double relmse;         /* of the render against the reference (eps 0.01) */
    double accept;         /* small steps: mean min(1, a) */
    double err_var;        /* variance of the error field (luminance) */
    double *rho_x, *rho_y; /* maxlag + 1 each, caller frees */
    double *err;           /* the error field, w*h, caller frees */
};

/* Renders with the camera's current size; false with a message on failure. */
struct image *wall_run(const struct scene *sc, const struct wall_cfg *c, uint64_t seed, const struct image *ref,
                       struct wall_meas *m, char *err, size_t errlen);
void wall_meas_free(struct wall_meas *m);

#endif
