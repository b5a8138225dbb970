/* Smooth conductor and its special case, the ideal mirror: one delta reflection lobe tinted by
 * albedo, with the exact conductor Fresnel term (complex IOR eta + i k per channel) for the
 * conductor (Tungsten's ConductorBsdf) and reflectance 1 for the mirror (MirrorBsdf). No numbers
 * are consumed; invert only checks that wo is the reflection. */
#include "bsdf/bsdf.h"
#include "bsdf/bsdf_smooth.h"
#include "bsdf/fresnel.h"

static bool conductor_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                             struct bsdf_sample *out)
{
    (void)s;
    (void)mode;
    if (wi.z <= 0) return false;
    out->wo = smooth_reflect(wi);
    out->pdf = 1;
    out->weight = c->albedo;
    if (c->b->type == BSDF_CONDUCTOR) out->weight = vmul(out->weight, fresnel_conductor(wi.z, c->b->eta, c->b->k));
    out->delta = true;
    out->lobe = CONDUCTOR_LOBE_REFLECT;
    return true;
}

static rgb conductor_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    (void)c, (void)wi, (void)wo, (void)mode;
    return v3s(0);
}

static double conductor_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    (void)c, (void)wi, (void)wo;
    return 0;
}

static bool conductor_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    (void)c, (void)w;
    return wi.z > 0 && smooth_same_dir(wo, smooth_reflect(wi));
}

const struct bsdf_ops bsdf_conductor_ops = {
    .dims = 0,
    .sample = conductor_sample,
    .eval = conductor_eval,
    .pdf = conductor_pdf,
    .invert = conductor_invert,
    .transmissive = false,
    .delta_only = true,
};
