/* Helpers shared by the smooth-BSDF test files: parameter sets, incident directions, a sampler
 * driven by the chi-square harness's rng, and one inversion round trip. */
#ifndef BSDF_SMOOTH_UTIL_H
#define BSDF_SMOOTH_UTIL_H

#include "base/rng.h"
#include "bsdf/bsdf.h"
#include "bsdf/bsdf_smooth.h"
#include "sampler/sampler.h"
#include <string.h>

/* Unit direction with the given cos(theta) and phi. */
static inline vec3 dir_cos_phi(double c, double phi)
{
    double s = sqrt(fmax(0.0, 1.0 - c * c));
    return v3(s * cos(phi), s * sin(phi), c);
}

static inline struct bsdf make_bsdf(enum bsdf_type t)
{
    struct bsdf b;
    memset(&b, 0, sizeof b);
    b.type = t;
    b.albedo = v3s(1);
    b.ior = 1.5;
    b.enable_refraction = true;
    b.eta = v3(0.200438, 0.924033, 1.10221); /* Cu, Tungsten's default conductor */
    b.k = v3(3.91295, 2.45285, 2.14219);
    b.thickness = 1;
    bsdf_prepare(&b);
    return b;
}

/* Incident directions above the surface: normal, two oblique, grazing (cos = 0.05). */
#define N_WI_UP 4
static const double wi_up_cos[N_WI_UP] = {1.0, 0.8, 0.4, 0.05};
static inline vec3 wi_up(int i) { return dir_cos_phi(wi_up_cos[i], 0.3 + 1.1 * i); }

#define RT_VERTEX 3

/* Sample wi with s, invert into w, replay: returns 0 on success, 1 forward failure, 2 inversion
 * failure, 3 replay mismatch (other wo or lobe), 4 a pass that did not consume/put exactly
 * ops->dims numbers. *out is the forward sample; *u0 the first number put (NAN if none). */
static inline int roundtrip_once(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, struct sampler_writer *w,
                                 enum transport mode, struct bsdf_sample *out, double *u0)
{
    const struct bsdf_ops *ops = bsdf_ops_for(c->b->type);
    sampler_begin(s, STREAM_CAMERA, RT_VERTEX);
    if (!ops->sample(c, wi, s, mode, out)) return 1;
    if (s->offset != ops->dims) return 4;
    int base = RT_VERTEX * SAMPLER_BLOCK;
    for (int i = 0; i < SAMPLER_BLOCK; i++)
        w->u[STREAM_CAMERA][base + i] = NAN;
    sampler_begin(&w->base, STREAM_CAMERA, RT_VERTEX);
    if (!ops->invert(c, wi, out->wo, &w->base)) return 2;
    if (w->base.offset != ops->dims) return 4;
    *u0 = w->u[STREAM_CAMERA][base];
    struct sampler_replay rp;
    sampler_replay_init(&rp, (const double(*)[STREAM_DIMS])w->u);
    sampler_begin(&rp.base, STREAM_CAMERA, RT_VERTEX);
    struct bsdf_sample back;
    if (!ops->sample(c, wi, &rp.base, mode, &back)) return 3;
    if (rp.base.offset != ops->dims) return 4;
    if (back.lobe != out->lobe || back.delta != out->delta || vlen(vsub(back.wo, out->wo)) > 1e-6) return 3;
    return 0;
}

/* A coloured, absorbing plastic: every term of the model is active. */
static inline struct bsdf plastic_coloured(void)
{
    struct bsdf b = make_bsdf(BSDF_PLASTIC);
    b.albedo = v3(0.8, 0.3, 0.05);
    b.ior = 1.8;
    b.thickness = 0.5;
    b.sigma_a = v3(0.5, 0.1, 2.0);
    bsdf_prepare(&b);
    return b;
}

#endif
