/* Expected-value splatting of a chain's current and proposed states (Veach's "expected values",
 * thesis §3.7 and MMLT paper Alg. 1-2): every proposal, accepted or not, is splatted with weight a
 * (its acceptance probability) and the current state with 1 - a, each times the chain's
 * b_k / P(k) over its own target. The current state's share is deferred: a chain owes it in
 * `pending` and pays it once, with the sum, when its state is replaced or the run ends.
 *
 * With --large-step-mis (PSSMLT, Kelemen et al. 2002) a large step's proposal is also an
 * independent sample of the uniform density, an estimate of its own weighted 1 / p_large; the two
 * are combined by the balance heuristic over the densities f / b (the chain's stationary one) and
 * p_large: every weight's denominator f / b becomes f / b + p_large, and a large step's proposal
 * counts a + 1. For f = 0 nothing is splatted either way. */
#ifndef SPLAT_EV_H
#define SPLAT_EV_H

#include "io/image.h"
#include "mcmc/chain.h"

/* Every splat of l, its colour times wgt (nothing when wgt <= 0); a non-finite product is counted
 * in *dropped instead. */
void splat_list_weighted(struct image *img, const struct splat_list *l, double wgt, long *dropped);
/* One proposal (splats l, target f; f = 0: nothing to splat) decided with acceptance probability a:
 * the proposal's share now, the current state's owed. */
void splat_ev(struct image *img, struct chain *c, const struct splat_list *l, double f, double a);
/* The same for a step that may be large, under --large-step-mis (c->mis_pl > 0), else splat_ev. */
void splat_ev_step(struct image *img, struct chain *c, const struct splat_list *l, double f, double a, bool large);
/* The current state's share 1 - a of one proposal, owed. */
void owe_current(struct chain *c, double a);
/* Splats what the current state is owed. */
void pay_current(struct image *img, struct chain *c);
/* Replaces the chain's state by an accepted one (splat list l, target f), after paying the old. */
void move_to(struct image *img, struct chain *c, const struct splat_list *l, double f);

#endif
