/* PCG32 (O'Neill): small state, independent streams per (seed, thread, chain).
 * Every run is reproducible from its seed; never use rand() or time-based seeds. */
#ifndef RNG_H
#define RNG_H

#include <stdint.h>

typedef struct { uint64_t state, inc; } rng;

void rng_seed(rng *r, uint64_t seed, uint64_t stream);
uint32_t rng_u32(rng *r);
/* Uniform double in [0, 1) with 53 random bits. */
double rng_uniform(rng *r);

#endif
