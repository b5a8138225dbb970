/* Reference image of the CMLT toy by plain (stratified) Monte Carlo with techniques chosen for low
 * variance, independent of the two charts under test:
 *   light 1: balance-heuristic MIS of emission sampling on light 1 (pdf Le1*(l)/Phi_1) and
 *            cosine-direction sampling (pdf G/pi), the latter kept only when it hits light 1;
 *   light 2: a uniform point on the hole, the ray through it continued to the light; pdf in light
 *            area measure 1/(A_hole lambda^2), lambda = (L2_Y - g_y)/(1 - g_y) (central projection
 *            between parallel planes); f/pdf is smooth, so the tiny hole costs nothing.
 * Ground points are jittered on a sqrt(spp) x sqrt(spp) grid per pixel. */
#ifndef CMLT_REFERENCE_H
#define CMLT_REFERENCE_H

#include <stdint.h>

struct progress; /* base/parallel.h */

struct cmlt_ref_result {
    double b[3];       /* integrals of f*, w_1 f*, w_2 f* over path space */
    double noise_rmse; /* estimated RMSE of the reference itself (from per-pixel sample variance) */
};

/* img: w*h*3 doubles. Rows are spread over `threads` threads; deterministic for a given seed. */
void cmlt_reference(int w, int h, int spp, uint64_t seed, int threads, double *img, struct cmlt_ref_result *res,
                    struct progress *progress);

#endif
