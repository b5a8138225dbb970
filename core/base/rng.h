/* PCG32 (O'Neill): small state, independent streams per (seed, thread, chain).
 * Every run is reproducible from its seed; never use rand() or time-based seeds. */
#ifndef RNG_H
#define RNG_H

#include <stdint.h>

typedef struct {
    uint64_t state, inc;
} rng;

void rng_seed(rng *r, uint64_t seed, uint64_t stream);

/* PCG-XSH-RR 64/32 with the stream selector in the increment. Inline: every sampler and every
 * Metropolis step draws from it. */
static inline uint32_t rng_u32(rng *r)
{
    uint64_t old = r->state;
    r->state = old * 6364136223846793005ULL + r->inc;
    uint32_t xorshifted = (uint32_t)(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = (uint32_t)(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((-rot) & 31));
}

/* Uniform double in [0, 1) on the grid of 2^-32: one generator step per number. Sampling needs no
 * finer grid (images have < 2^16 pixels per axis; float rays resolve 2^-24), and small steps in
 * primary sample space move numbers off the grid anyway. Two steps per number cost 4-6 % of a
 * path-tracing sample. */
static inline double rng_uniform(rng *r) { return rng_u32(r) * (1.0 / 4294967296.0); }

#endif
