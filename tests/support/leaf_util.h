/* Shared set-up for the leaf-BSDF tests (test_bsdf_leaf.c, test_bsdf_leaf_stat.c): materials with
 * Tungsten's defaults and the scene's variants, incident directions on both sides, and a sampler
 * that records the numbers sample() draws, for the round trip u -> sample -> invert -> u'. */
#ifndef LEAF_UTIL_H
#define LEAF_UTIL_H

#include "base/rng.h"
#include "bsdf/bsdf.h"
#include "bsdf/bsdf_leaf.h"
#include "sampler/sampler.h"
#include <string.h>

static inline struct bsdf leaf_bsdf(enum bsdf_type t)
{
    struct bsdf b;
    memset(&b, 0, sizeof b);
    b.type = t;
    b.albedo = v3s(1);
    b.ior = 1.5;
    b.thickness = t == BSDF_THINSHEET ? 0.5 : 1;
    b.roughness = t == BSDF_OREN_NAYAR ? 1 : 0.1;
    b.transmittance = 0.5;
    b.exponent = 64;
    b.diffuse_ratio = 0.2;
    bsdf_prepare(&b);
    return b;
}

static inline struct bsdf leaf_on(double roughness, rgb albedo)
{
    struct bsdf b = leaf_bsdf(BSDF_OREN_NAYAR);
    b.roughness = roughness;
    b.albedo = albedo;
    return b;
}

static inline struct bsdf leaf_phong(double n, double d, rgb albedo)
{
    struct bsdf b = leaf_bsdf(BSDF_PHONG);
    b.exponent = n;
    b.diffuse_ratio = d;
    b.albedo = albedo;
    return b;
}

static inline struct bsdf leaf_dt(double t, rgb albedo)
{
    struct bsdf b = leaf_bsdf(BSDF_DIFFUSE_TRANSMISSION);
    b.transmittance = t;
    b.albedo = albedo;
    return b;
}

static inline struct bsdf leaf_sheet(double ior, double thickness, rgb sigma_a)
{
    struct bsdf b = leaf_bsdf(BSDF_THINSHEET);
    b.ior = ior;
    b.thickness = thickness;
    b.sigma_a = sigma_a;
    return b;
}

static inline vec3 leaf_dir(double c, double phi)
{
    double s = sqrt(fmax(0.0, 1.0 - c * c));
    return v3(s * cos(phi), s * sin(phi), c);
}

/* Incident cosines: normal, oblique, shallow, grazing. */
#define LEAF_NWI 4
static const double leaf_wi_cos[LEAF_NWI] = {1.0, 0.8, 0.4, 0.05};
static inline vec3 leaf_wi(int i, bool below)
{
    vec3 w = leaf_dir(leaf_wi_cos[i], 0.3 + 1.1 * i);
    if (below) w.z = -w.z;
    return w;
}

/* A forward sampler drawing from an rng and keeping what it drew. */
struct rec_sampler {
    struct sampler base;
    rng *r;
    double u[SAMPLER_BLOCK];
    int n;
};
static inline double rec_next(struct sampler *s, enum dim_kind kind)
{
    (void)kind;
    struct rec_sampler *q = (struct rec_sampler *)s;
    double u = rng_uniform(q->r);
    if (q->n < SAMPLER_BLOCK) q->u[q->n++] = u;
    return u;
}
static const struct sampler_ops rec_ops = {rec_next, NULL, NULL};
static inline void rec_begin(struct rec_sampler *q, rng *r)
{
    q->base = (struct sampler){&rec_ops, 0, 0, 0};
    q->r = r;
    q->n = 0;
    sampler_begin(&q->base, STREAM_CAMERA, 1);
}

/* One round trip at vertex 1 of the camera stream: sample with fresh numbers (kept in q->u),
 * invert the sampled wo into w (w->u[STREAM_CAMERA][SAMPLER_BLOCK + k]), replay them into *back.
 * 0 success, 1 forward failure, 2 inversion failure, 3 replay failure, 4 wrong count of numbers. */
static inline int leaf_roundtrip(const struct bsdf_ctx *c, vec3 wi, rng *r, struct rec_sampler *q,
                                 struct sampler_writer *w, struct bsdf_sample *out, struct bsdf_sample *back)
{
    const struct bsdf_ops *ops = bsdf_ops_for(c->b->type);
    rec_begin(q, r);
    if (!ops->sample(c, wi, &q->base, TRANSPORT_RADIANCE, out)) return 1;
    if (q->n != ops->dims) return 4;
    sampler_writer_clear(w);
    sampler_begin(&w->base, STREAM_CAMERA, 1);
    if (!ops->invert(c, wi, out->wo, &w->base)) return 2;
    if (w->base.offset != ops->dims) return 4;
    struct sampler_replay rp;
    sampler_replay_init(&rp, (const double(*)[STREAM_DIMS])w->u);
    sampler_begin(&rp.base, STREAM_CAMERA, 1);
    if (!ops->sample(c, wi, &rp.base, TRANSPORT_RADIANCE, back)) return 3;
    return rp.base.offset == ops->dims ? 0 : 4;
}

#endif
