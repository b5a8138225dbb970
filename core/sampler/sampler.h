/* The annotated sampler: the one source of random numbers for all path code (DESIGN.md).
 *
 * Path code never calls an RNG. Before the numbers of a vertex it calls sampler_begin(stream,
 * vertex); then every sampler_next() names what the number drives. Numbers of a vertex occupy a
 * fixed block of SAMPLER_BLOCK dimensions in the vector of their stream (thesis §3.7.1), so a
 * change at one vertex never shifts the numbers of the next.
 *
 * Inversion (thesis §5.1) runs the same calls through a writer: inverse sampling functions call
 * sampler_put() in exactly the order their forward function calls sampler_next(), and draw the
 * fresh random numbers xi of Eq. 5.6-5.8 from sampler_fresh().
 *
 * Every implementation (a struct with `struct sampler base` first, and its sampler_ops):
 *   sampler/sampler.c     the independent sampler, the writer (inversion), the replay, and the
 *                         one-block sampler an inversion writes and a BSDF reads (sampler_block)
 *   sampler/pss.c         struct pss_sampler: MLT's primary-sample-space state, lazy small steps
 *   mc/render.c           struct pixel_sampler: PT/BDPT's per-pixel numbers, independent or Sobol
 *   mcmc/controlled_step.c struct ctrl_sampler: the controlled and root small steps (thesis §5.3)
 *   mcmc/pitp.c           struct block_sampler: a block PITP's inversion writes and its retrace reads
 *   path/path_invert.c    struct tee: passes an inversion's numbers on and replays its block
 *   bsdf/bsdf_nested.c    struct probe_io: a nested BSDF's inverse probed through its forward */
#ifndef SAMPLER_H
#define SAMPLER_H

#include "base/rng.h"
#include <assert.h>
#include <stdbool.h>

enum dim_kind {
    DIM_CONTINUOUS, /* drives a continuous mapping (direction, position) */
    DIM_DISCRETE,   /* drives a discrete decision (lobe, reflect/refract, light choice, RR) */
    DIM_IMAGE_X,    /* image-plane position of the camera subpath */
    DIM_IMAGE_Y,
    DIM_TECHNIQUE /* MMLT's technique index: small steps mutate it like a continuous number
                     (MMLT §4), constrained discrete choices leave it free */
};

enum { STREAM_CAMERA = 0, STREAM_EMITTER = 1, STREAM_TECHNIQUE = 2, STREAM_COUNT = 3 };

#define SAMPLER_BLOCK 8 /* dimensions per vertex */
/* Segments; subpaths hold at most MAX_PATH_LENGTH + 1 vertices. 64 is Tungsten's default
 * max_bounces, so most Tungsten scenes fit; the loader clamps longer limits with a warning.
 * Every fixed-size per-path array of the core is sized from it. */
#define MAX_PATH_LENGTH 64
#define MAX_SUBPATH_VERTS (MAX_PATH_LENGTH + 2)
#define STREAM_DIMS (MAX_SUBPATH_VERTS * SAMPLER_BLOCK)

struct sampler;
struct sampler_ops {
    double (*next)(struct sampler *s, enum dim_kind kind);        /* forward */
    void (*put)(struct sampler *s, enum dim_kind kind, double u); /* writers only */
    double (*fresh)(struct sampler *s);                           /* writers only */
};

/* Implementations embed this as their first member. */
struct sampler {
    const struct sampler_ops *ops;
    int stream, vertex, offset;
};

static inline int sampler_index(const struct sampler *s) { return s->vertex * SAMPLER_BLOCK + s->offset; }
static inline void sampler_begin(struct sampler *s, int stream, int vertex)
{
    assert(stream >= 0 && stream < STREAM_COUNT && vertex >= 0 && vertex < MAX_SUBPATH_VERTS);
    s->stream = stream;
    s->vertex = vertex;
    s->offset = 0;
}
static inline double sampler_next(struct sampler *s, enum dim_kind kind)
{
    assert(s->offset < SAMPLER_BLOCK);
    double u = s->ops->next(s, kind);
    s->offset++;
    return u;
}
static inline void sampler_put(struct sampler *s, enum dim_kind kind, double u)
{
    assert(s->offset < SAMPLER_BLOCK && s->ops->put);
    s->ops->put(s, kind, u);
    s->offset++;
}
static inline double sampler_fresh(struct sampler *s) { return s->ops->fresh(s); }

/* Eq. 5.6: a discrete outcome with interval [lo, hi) inverts to a uniform point inside it.
 * The result is nudged inside the half-open interval so that replay picks the same outcome. */
double invert_discrete(double lo, double hi, double xi);

/* Plain Monte Carlo: every number fresh. */
struct sampler_independent {
    struct sampler base;
    rng r;
};
void sampler_independent_init(struct sampler_independent *s, uint64_t seed, uint64_t stream);

/* Writer for inversion: records the numbers put for every (stream, vertex, offset) and their
 * annotations; unwritten slots keep NAN so a test can tell them apart. */
struct sampler_writer {
    struct sampler base;
    rng r;
    double u[STREAM_COUNT][STREAM_DIMS];
    unsigned char kind[STREAM_COUNT][STREAM_DIMS];
};
void sampler_writer_init(struct sampler_writer *w, uint64_t seed, uint64_t stream);
void sampler_writer_clear(struct sampler_writer *w);

/* Replays a fixed vector (e.g. one filled by a writer); the forward counterpart used by round-trip
 * tests and by the MCMC state. Reading an unset (NAN) slot aborts: a replay must not invent numbers. */
struct sampler_replay {
    struct sampler base;
    const double (*u)[STREAM_DIMS];
};
void sampler_replay_init(struct sampler_replay *s, const double (*u)[STREAM_DIMS]);

/* A forward sampler that reads every number from a borrowed generator: the fresh numbers of
 * Veach's mutations (mcmc/veach_bidir.c, the chain's own generator, checkpointed with it) and the
 * BSDF tests' draws. */
struct sampler_rng {
    struct sampler base;
    rng *r;
};
void sampler_rng_init(struct sampler_rng *s, rng *r);

/* One block of numbers that an inversion writes (put) and a forward sampling function then reads
 * (next), whatever stream and vertex either says: the local inverse-then-sample of one vertex
 * (controlled steps, a path's subpaths re-formed, path/path_form.c). Fresh numbers come from r, or
 * are 0.5 when r is NULL (where any value gives the same result, and re-forming must not draw). */
struct sampler_block {
    struct sampler base;
    double *u; /* SAMPLER_BLOCK numbers */
    int n;     /* how many were put */
    rng *r;
};
void sampler_block_init(struct sampler_block *b, double *u, rng *r);

#endif
