/* The per-technique split of an evaluated state for the technique images (stats/tech_image.h; MMLT
 * paper §5, Fig. 5): which of the k + 1 techniques of length k the state contributes through, and
 * with what splat. An MMLT state is in one technique, its technique number's; a PSSMLT state
 * evaluates all of them at once, so its subpaths are connected again here at length k. */
#ifndef TECH_SPLIT_H
#define TECH_SPLIT_H

#include "mc/integrator.h"
#include "stats/tech_image.h"

/* Hands a the split of the state just evaluated (start: a chain's first state; else a proposal):
 * chain_k the evaluated MMLT chain's length, whose state `l` is in technique `tech`; 0 for PSSMLT,
 * whose subpaths are w's (lengths w->nz, w->ny). Nothing is computed for a chain a does not track. */
void tech_split_record(struct tech_acc *a, const struct path_ctx *pc, const struct scratch *w, int chain_k, int tech,
                       const struct splat_list *l, bool start);

#endif
