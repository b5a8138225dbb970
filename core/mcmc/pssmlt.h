/* PSSMLT's state evaluation (thesis §3.7, Eq. 3.32-3.35; MMLT paper Alg. 1): a state is one pair
 * of subpaths traced to the full length from its numbers, and its target is the luminance of the
 * MIS-weighted sum of all their connections of every length (BDPT as the path sample function, as
 * the thesis's Chapter 6 uses it; Kelemen's maximum heuristic with path_ctx.max_heuristic). */
#ifndef PSSMLT_H
#define PSSMLT_H

#include "mc/integrator.h"

/* The state read from sampler s: its splats into out (one per t = 1 connection, then the sum of the
 * others at z_0's pixel), the subpaths left in w, and the scalar target (0 for none). */
double pssmlt_eval_state(const struct path_ctx *pc, struct sampler *s, struct scratch *w, struct splat_list *out);

#endif
