/* PCG32 (O'Neill): small state, independent streams per (seed, thread, chain).
 * Every run is reproducible from its seed; never use rand() or time-based seeds. */
#ifndef RNG_H
#define RNG_H

#include <stdint.h>

typedef struct { uint64_t state, inc; } rng;

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

/* Uniform double in [0, 1) with 53 random bits. */
static inline double rng_uniform(rng *r)
{
    uint64_t hi = rng_u32(r) >> 5, lo = rng_u32(r) >> 6; /* 27 + 26 = 53 bits */
    return (double)(hi * 67108864.0 + lo) * (1.0 / 9007199254740992.0);
}

#endif
