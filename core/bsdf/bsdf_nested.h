/* Shared machinery of the nested BSDFs (transparency, smooth_coat, rough_coat, mixed): the fixed
 * block layout, lobe numbering, and the inverse's choice among the lobes and children that can
 * produce a given wo (thesis Eq. 5.7).
 *
 * Layout: a nested BSDF draws its own discrete number first, then the numbers of the one child (or
 * own continuous lobe) it chose, then pads with unused numbers up to its dims, so that every
 * outcome consumes the same count; invert() fills the padding with sampler_fresh().
 *
 * Lobes reported in bsdf_sample.lobe: a nested BSDF's own lobes are 0 (the coat's reflection,
 * transparency's pass-through); child i's lobe l is NESTED_LOBE(i, l). */
#ifndef BSDF_NESTED_H
#define BSDF_NESTED_H

#include "bsdf/bsdf.h"

#define NESTED_LOBE(child, lobe) (16 * ((child) + 1) + (lobe))

/* Consumes (forward) or fills with fresh numbers (inverse) the rest of a block that ends at `end`. */
void nested_pad_next(struct sampler *s, int end);
void nested_pad_put(struct sampler *w, int end);

/* How a child reaches wo: its inverse's numbers, kept to be written later, and whether the sample
 * they replay to is a delta lobe (then p_delta is its discrete probability). */
struct nested_probe {
    bool ok, delta;
    double p_delta;
    int n;
    double u[SAMPLER_BLOCK];
    enum dim_kind kind[SAMPLER_BLOCK];
};

/* Inverts child c at (wi, wo) into a buffer (fresh numbers drawn from w) and replays sample() on
 * it to learn whether wo is one of its delta directions. */
void nested_probe(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w, struct nested_probe *p);
/* Writes a probe's numbers to w, in order. */
void nested_put(struct sampler *w, const struct nested_probe *p);

/* Index among n candidates, drawn with one sampler_fresh(w): a candidate with delta weight
 * dw[i] > 0 (the discrete probability of reaching wo through it) wins over every continuous one,
 * since continuous lobes reach a delta direction with probability zero; among the same kind, in
 * proportion to the weights (continuous: cw[i] = choice probability times pdf, Eq. 5.7).
 * -1 when all weights are 0. */
int nested_pick(struct sampler *w, int n, const double *dw, const double *cw);

/* Probability with which the mixed BSDF of c picks child 0: its constant ratio or its scalar ratio
 * texture at c's uv, clamped to [0, 1]. */
double mixed_ratio(const struct bsdf_ctx *c);

#endif
