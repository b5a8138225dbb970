/* Rough conductor: Torrance-Sparrow microfacet reflection (Walter et al. 2007 Eq. 20) with the
 * conductor Fresnel term, after Tungsten's RoughConductorBsdf.cpp.
 *
 *   f(wi, wo) = albedo F(wi.h) D(h) G(wi, wo, h) / (4 wi.z wo.z),   h = normalize(wi + wo)
 *   pdf(wo)   = D(h) h.z / (4 wi.h)                                  (Walter Eq. 14 Jacobian)
 *
 * Sampling: 2 continuous numbers -> microfacet normal m ~ D(m) m.z with alpha itself (Tungsten
 * leaves the roughness widening disabled for conductors), wo = reflect(wi, m). Fails when
 * wi.m <= 0 or wo.z <= 0. Inverse: h -> (u1, u2) by mf_invert; no discrete numbers.
 * Reflection only, wi.z > 0 (the path code flips the frame): not transmissive. Lobe 0. */
#include "bsdf/bsdf.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"

static bool rc_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                      struct bsdf_sample *out)
{
    (void)mode;
    const struct bsdf *b = c->b;
    double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS);
    if (wi.z <= 0) return false;
    double alpha = mf_alpha(c->roughness);
    vec3 m = mf_sample(b->dist, alpha, u1, u2);
    double wim = vdot(wi, m);
    if (wim <= 0) return false;
    vec3 wo = mf_reflect(wi, m);
    if (wo.z <= 0) return false;
    double pm = mf_pdf(b->dist, alpha, m);
    if (!(pm > 0)) return false;
    double G = mf_G(b->dist, alpha, wi, wo, m);
    out->wo = wo;
    out->pdf = pm / (4 * wim);
    /* f wo.z / pdf = F D G / (4 wi.z) * 4 wi.m / (D m.z) */
    out->weight = vscale(vmul(c->albedo, fresnel_conductor(wim, b->eta, b->k)), wim * G / (wi.z * m.z));
    out->delta = false;
    out->lobe = 0;
    return true;
}

static rgb rc_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    (void)mode;
    const struct bsdf *b = c->b;
    vec3 h;
    if (wi.z <= 0 || wo.z <= 0 || !mf_half_reflect(wi, wo, &h)) return v3s(0);
    double alpha = mf_alpha(c->roughness), wih = vdot(wi, h);
    double fr = mf_D(b->dist, alpha, h) * mf_G(b->dist, alpha, wi, wo, h) / (4 * wi.z * wo.z);
    return vscale(vmul(c->albedo, fresnel_conductor(wih, b->eta, b->k)), fr);
}

static double rc_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    const struct bsdf *b = c->b;
    vec3 h;
    if (wi.z <= 0 || wo.z <= 0 || !mf_half_reflect(wi, wo, &h)) return 0;
    double wih = vdot(wi, h);
    if (wih <= 0) return 0;
    return mf_pdf(b->dist, mf_alpha(c->roughness), h) / (4 * wih);
}

static bool rc_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    const struct bsdf *b = c->b;
    vec3 h;
    double u1, u2;
    if (wi.z <= 0 || wo.z <= 0 || !mf_half_reflect(wi, wo, &h) || vdot(wi, h) <= 0) return false;
    if (!mf_invert(b->dist, mf_alpha(c->roughness), h, &u1, &u2)) return false;
    sampler_put(w, DIM_CONTINUOUS, u1);
    sampler_put(w, DIM_CONTINUOUS, u2);
    return true;
}

const struct bsdf_ops bsdf_rough_conductor_ops = {
    .dims = 2,
    .sample = rc_sample,
    .eval = rc_eval,
    .pdf = rc_pdf,
    .invert = rc_invert,
    .transmissive = false,
    .delta_only = false,
};
