/* Diffuse transmission (Tungsten's diffuse_transmission): a Lambertian lobe on each side,
 *   f(wi, wo) = albedo (1 - t) / pi  with wo on wi's side,  albedo t / pi  on the other,
 * t = b->transmittance. One discrete number picks the side (reflection on [0, 1 - t), as Tungsten
 * with its probability t of transmitting), two continuous ones the cosine-weighted direction,
 * mirrored to the chosen side, so every sample weighs exactly albedo and a white sheet conserves
 * energy. f depends on wi and wo only through whether they share a side: reciprocal. Both sides
 * alike (transmissive: never flipped). */
#include "bsdf/bsdf.h"
#include "bsdf/bsdf_leaf.h"
#include "sampling/warp.h"

static double p_side(const struct bsdf *b, bool transmit) { return transmit ? b->transmittance : 1 - b->transmittance; }

static bool dt_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                      struct bsdf_sample *out)
{
    (void)mode;
    if (wi.z == 0) return false;
    double u = sampler_next(s, DIM_DISCRETE);
    double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS);
    bool transmit = !(u < p_side(c->b, false));
    vec3 wo = warp_cosine_hemisphere(u1, u2);
    if ((wi.z < 0) != transmit) wo.z = -wo.z;
    double pdf = p_side(c->b, transmit) * fabs(wo.z) * INV_PI;
    if (!(pdf > 0)) return false;
    out->wo = wo;
    out->pdf = pdf;
    out->weight = c->albedo; /* albedo p / pi |cos| / (p |cos| / pi) */
    out->delta = false;
    out->lobe = transmit ? DIFFTRANS_LOBE_TRANSMIT : DIFFTRANS_LOBE_REFLECT;
    return true;
}

static rgb dt_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    (void)mode;
    if (wi.z == 0 || wo.z == 0) return v3s(0);
    return vscale(c->albedo, p_side(c->b, wi.z * wo.z < 0) * INV_PI);
}

static double dt_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    if (wi.z == 0 || wo.z == 0) return 0;
    return p_side(c->b, wi.z * wo.z < 0) * fabs(wo.z) * INV_PI;
}

static bool dt_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    if (wi.z == 0 || wo.z == 0) return false;
    bool transmit = wi.z * wo.z < 0;
    double pr = p_side(c->b, false);
    if (!(p_side(c->b, transmit) > 0)) return false;
    double u1, u2;
    warp_cosine_hemisphere_invert(wo, &u1, &u2); /* reads x, y only: either side */
    sampler_put(w, DIM_DISCRETE,
                transmit ? invert_discrete(pr, 1.0, sampler_fresh(w)) : invert_discrete(0.0, pr, sampler_fresh(w)));
    sampler_put(w, DIM_CONTINUOUS, u1);
    sampler_put(w, DIM_CONTINUOUS, u2);
    return true;
}

const struct bsdf_ops bsdf_diffuse_transmission_ops = {
    .dims = 3,
    .sample = dt_sample,
    .eval = dt_eval,
    .pdf = dt_pdf,
    .invert = dt_invert,
    .transmissive = true,
    .delta_only = false,
};
