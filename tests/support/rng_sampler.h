/* A forward sampler reading from a borrowed rng: the chi-square harness owns the rng and the
 * sampling code under test draws through the sampler interface. Shared by the BSDF tests. */
#ifndef RNG_SAMPLER_H
#define RNG_SAMPLER_H

#include "base/rng.h"
#include "sampler/sampler.h"

struct rng_sampler {
    struct sampler base;
    rng *r;
};
static inline double rng_sampler_next(struct sampler *s, enum dim_kind kind)
{
    (void)kind;
    return rng_uniform(((struct rng_sampler *)s)->r);
}
static const struct sampler_ops rng_sampler_ops = {rng_sampler_next, NULL, NULL};
static inline void rng_sampler_init(struct rng_sampler *s, rng *r)
{
    s->base = (struct sampler){&rng_sampler_ops, 0, 0, 0};
    s->r = r;
}

#endif
