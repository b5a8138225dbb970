/* The fused perturbations' pieces (fused.c; docs/fused.md), shared by its mutation and its tests:
 * an MMLT path as the state Veach's perturbations move, and a perturbed path mapped back to the
 * primary sample space of the chain's technique. */
#ifndef FUSED_H
#define FUSED_H

#include "mcmc/veach.h"

/* The path x (its splat at raster position px, py) as a Veach state; the connection's ends
 * scatter through no lobe, whatever flags their walks left. */
void fused_state_of(struct veach_state *st, const struct mmlt_path *x, double px, double py);
/* The perturbed path yp[0..k] (x's length, x's vertices up to x_{lo-1}; lo = 0: all of it new) in
 * x's technique, w->xz (x->t camera vertices) and w->xs (x->s emitter vertices), inverted into wr's
 * camera and emitter numbers: the camera subpath whole, the emitter subpath from the block that
 * reaches x'_lo on (none when it ends before; the numbers of the others, and the technique number,
 * are the caller's). False when the technique cannot produce it: an inversion fails. */
bool fused_invert(const struct path_ctx *pc, const struct mmlt_path *x, const struct vertex *const *yp, int lo,
                  struct veach_scratch *w, struct sampler *wr);
/* Whether y's walks retraced the subpaths fused_invert inverted (w->xz, and w->xs when the emitter
 * subpath has a vertex from x'_lo on) within tol. */
bool fused_retraced(const struct mmlt_path *y, int lo, const struct veach_scratch *w, double tol);

#endif
