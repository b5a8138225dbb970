/* Smooth dielectric interface (glass). One discrete number chooses reflection with probability
 * F (the Fresnel reflectance) or refraction with 1 - F, thesis Eq. 5.1; its inverse is Eq. 5.4.
 * wi.z < 0 means wi lies inside the medium of index ior (outside = 1). Without
 * enable_refraction only the reflection lobe exists (probability 1, weight F). Under total
 * internal reflection F = 1. Both lobes are tinted by albedo, as in Tungsten's DielectricBsdf.
 * Refraction in TRANSPORT_RADIANCE carries (eta_wi_side / eta_wo_side)^2 (Veach §5.2). */
#include "bsdf/bsdf.h"
#include "bsdf/bsdf_smooth.h"
#include "bsdf/fresnel.h"

/* The interface as seen from wi: eta = eta_wo_side / eta_wi_side for refraction, F, cos_t. */
struct interface {
    double eta, F, cos_t, p_reflect;
};

static struct interface interface_at(const struct bsdf *b, vec3 wi)
{
    struct interface it;
    it.eta = wi.z < 0 ? 1.0 / b->ior : b->ior;
    it.F = fresnel_dielectric(fabs(wi.z), it.eta, &it.cos_t);
    it.p_reflect = b->enable_refraction ? it.F : 1.0;
    return it;
}

static bool dielectric_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                              struct bsdf_sample *out)
{
    if (wi.z == 0) return false;
    struct interface it = interface_at(c->b, wi);
    double u = sampler_next(s, DIM_DISCRETE);
    out->delta = true;
    if (u < it.p_reflect) {
        out->wo = smooth_reflect(wi);
        out->pdf = it.p_reflect;
        out->weight = vscale(c->albedo, it.F / it.p_reflect);
        out->lobe = DIELECTRIC_LOBE_REFLECT;
        return true;
    }
    if (it.F >= 1.0) return false; /* unreachable: p_reflect = 1 then */
    double scale = mode == TRANSPORT_RADIANCE ? 1.0 / (it.eta * it.eta) : 1.0;
    out->wo = smooth_refract(wi, it.eta, it.cos_t);
    out->pdf = 1.0 - it.p_reflect;
    out->weight = vscale(c->albedo, scale * (1.0 - it.F) / (1.0 - it.p_reflect));
    out->lobe = DIELECTRIC_LOBE_REFRACT;
    return true;
}

static rgb dielectric_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    (void)c, (void)wi, (void)wo, (void)mode;
    return v3s(0);
}

static double dielectric_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    (void)c, (void)wi, (void)wo;
    return 0;
}

static bool dielectric_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    if (wi.z == 0) return false;
    struct interface it = interface_at(c->b, wi);
    if (it.p_reflect > 0 && wo.z * wi.z > 0 && smooth_same_dir(wo, smooth_reflect(wi))) {
        sampler_put(w, DIM_DISCRETE, invert_discrete(0.0, it.p_reflect, sampler_fresh(w)));
        return true;
    }
    if (it.p_reflect < 1 && wo.z * wi.z < 0 && smooth_same_dir(wo, smooth_refract(wi, it.eta, it.cos_t))) {
        sampler_put(w, DIM_DISCRETE, invert_discrete(it.p_reflect, 1.0, sampler_fresh(w)));
        return true;
    }
    return false;
}

const struct bsdf_ops bsdf_dielectric_ops = {
    .dims = 1,
    .sample = dielectric_sample,
    .eval = dielectric_eval,
    .pdf = dielectric_pdf,
    .invert = dielectric_invert,
    .transmissive = true,
    .delta_only = true,
};
