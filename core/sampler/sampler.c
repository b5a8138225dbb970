/* Independent, writer and replay samplers (see sampler.h for the dimension layout). */
#include "sampler/sampler.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

double invert_discrete(double lo, double hi, double xi)
{
    double u = lo + xi * (hi - lo);
    if (u >= hi) u = nextafter(hi, lo);
    if (u < lo) u = lo;
    return u;
}

static double indep_next(struct sampler *s, enum dim_kind kind)
{
    (void)kind;
    return rng_uniform(&((struct sampler_independent *)s)->r);
}
static const struct sampler_ops indep_ops = {indep_next, NULL, NULL};

void sampler_independent_init(struct sampler_independent *s, uint64_t seed, uint64_t stream)
{
    s->base = (struct sampler){&indep_ops, 0, 0, 0};
    rng_seed(&s->r, seed, stream);
}

static double writer_next(struct sampler *s, enum dim_kind kind)
{
    (void)s;
    (void)kind;
    fprintf(stderr, "sampler_writer: forward sampling through a writer\n");
    abort();
}
static void writer_put(struct sampler *s, enum dim_kind kind, double u)
{
    struct sampler_writer *w = (struct sampler_writer *)s;
    int i = sampler_index(s);
    w->u[s->stream][i] = u;
    w->kind[s->stream][i] = (unsigned char)kind;
}
static double writer_fresh(struct sampler *s) { return rng_uniform(&((struct sampler_writer *)s)->r); }
static const struct sampler_ops writer_ops = {writer_next, writer_put, writer_fresh};

void sampler_writer_clear(struct sampler_writer *w)
{
    for (int st = 0; st < STREAM_COUNT; st++)
        for (int i = 0; i < STREAM_DIMS; i++) {
            w->u[st][i] = NAN;
            w->kind[st][i] = 0;
        }
}

void sampler_writer_init(struct sampler_writer *w, uint64_t seed, uint64_t stream)
{
    w->base = (struct sampler){&writer_ops, 0, 0, 0};
    rng_seed(&w->r, seed, stream);
    sampler_writer_clear(w);
}

static double replay_next(struct sampler *s, enum dim_kind kind)
{
    (void)kind;
    double u = ((struct sampler_replay *)s)->u[s->stream][sampler_index(s)];
    if (isnan(u)) {
        fprintf(stderr, "sampler_replay: stream %d vertex %d offset %d was never written\n", s->stream, s->vertex,
                s->offset);
        abort();
    }
    return u;
}
static const struct sampler_ops replay_ops = {replay_next, NULL, NULL};

void sampler_replay_init(struct sampler_replay *s, const double (*u)[STREAM_DIMS])
{
    s->base = (struct sampler){&replay_ops, 0, 0, 0};
    s->u = u;
}

static double block_next(struct sampler *s, enum dim_kind kind)
{
    (void)kind;
    return ((struct sampler_block *)s)->u[s->offset];
}
static void block_put(struct sampler *s, enum dim_kind kind, double u)
{
    (void)kind;
    struct sampler_block *b = (struct sampler_block *)s;
    b->u[s->offset] = u;
    b->n = s->offset + 1;
}
static double block_fresh(struct sampler *s)
{
    rng *r = ((struct sampler_block *)s)->r;
    return r ? rng_uniform(r) : 0.5;
}
static const struct sampler_ops block_ops = {block_next, block_put, block_fresh};

void sampler_block_init(struct sampler_block *b, double *u, rng *r)
{
    b->base = (struct sampler){&block_ops, 0, 0, 0};
    b->u = u;
    b->n = 0;
    b->r = r;
}

static double rng_next(struct sampler *s, enum dim_kind kind)
{
    (void)kind;
    return rng_uniform(((struct sampler_rng *)s)->r);
}
static const struct sampler_ops rng_ops = {rng_next, NULL, NULL};

void sampler_rng_init(struct sampler_rng *s, rng *r)
{
    s->base = (struct sampler){&rng_ops, 0, 0, 0};
    s->r = r;
}
