/* PCG32 seeding and stepping (rng.h). */
#include "base/rng.h"

void rng_seed(rng *r, uint64_t seed, uint64_t stream)
{
    r->state = 0;
    r->inc = (stream << 1u) | 1u;
    rng_u32(r);
    r->state += seed;
    rng_u32(r);
}
