/* Lambertian reflection: f = albedo / pi on the upper hemisphere, sampled by the cosine-weighted
 * polar map (warp.h), whose exact inverse makes invert() a closed form. Two continuous numbers. */
#include "bsdf/bsdf.h"
#include "bsdf/bsdf_smooth.h"
#include "sampling/warp.h"

static bool lambert_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                           struct bsdf_sample *out)
{
    (void)mode;
    if (wi.z <= 0) return false;
    double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS);
    vec3 wo = warp_cosine_hemisphere(u1, u2);
    double pdf = warp_cosine_hemisphere_pdf(wo);
    if (pdf <= 0) return false;
    out->wo = wo;
    out->pdf = pdf;
    out->weight = c->albedo; /* (albedo / pi) cos / (cos / pi) */
    out->delta = false;
    out->lobe = LAMBERT_LOBE_DIFFUSE;
    return true;
}

static rgb lambert_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    (void)mode;
    if (wi.z <= 0 || wo.z <= 0) return v3s(0);
    return vscale(c->albedo, INV_PI);
}

static double lambert_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    (void)c;
    if (wi.z <= 0 || wo.z <= 0) return 0;
    return warp_cosine_hemisphere_pdf(wo);
}

static bool lambert_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    (void)c;
    if (wi.z <= 0 || wo.z <= 0) return false;
    double u1, u2;
    warp_cosine_hemisphere_invert(wo, &u1, &u2);
    sampler_put(w, DIM_CONTINUOUS, u1);
    sampler_put(w, DIM_CONTINUOUS, u2);
    return true;
}

const struct bsdf_ops bsdf_lambert_ops = {
    .dims = 2,
    .sample = lambert_sample,
    .eval = lambert_eval,
    .pdf = lambert_pdf,
    .invert = lambert_invert,
    .transmissive = false,
    .delta_only = false,
};
