/* Modified Phong (Tungsten's phong), exponent n, diffuse ratio d:
 *   f = albedo (d / pi + (1 - d) (n + 2) / (2 pi) max(0, cos a)^n),  cos a = mirror(wi) . wo,
 * on the upper hemisphere (cos a is symmetric in wi and wo: reciprocal). Sampling as Tungsten's:
 * the glossy lobe with probability 1 - d, cos a = u1^(1 / (n + 1)) and phi = 2 pi u2 around
 * mirror(wi) (a direction below the surface is a failed sample), else the cosine hemisphere;
 * pdf = (1 - d) (n + 1) / (2 pi) cos^n a + d cos theta / pi, the weight f cos / pdf.
 * One discrete number (glossy on [0, 1 - d)), two continuous; invert picks the lobe in proportion
 * to its share of the pdf at wo. The lobe's frame is frame_from_normal(mirror(wi)) both ways. */
#include "bsdf/bsdf.h"
#include "bsdf/bsdf_leaf.h"
#include "bsdf/bsdf_smooth.h"
#include "sampling/warp.h"

static double glossy_pdf(const struct bsdf *b, double cos_a)
{
    return cos_a > 0 ? (b->exponent + 1) * 0.5 * INV_PI * pow(cos_a, b->exponent) : 0;
}

static double phong_pdf_up(const struct bsdf *b, vec3 wi, vec3 wo)
{
    double d = b->diffuse_ratio;
    return (1 - d) * glossy_pdf(b, vdot(smooth_reflect(wi), wo)) + d * wo.z * INV_PI;
}

static rgb phong_f(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    const struct bsdf *b = c->b;
    double d = b->diffuse_ratio, cos_a = vdot(smooth_reflect(wi), wo);
    double g = cos_a > 0 ? (b->exponent + 2) * 0.5 * INV_PI * pow(cos_a, b->exponent) : 0;
    return vscale(c->albedo, d * INV_PI + (1 - d) * g);
}

static bool phong_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                         struct bsdf_sample *out)
{
    (void)mode;
    if (wi.z <= 0) return false;
    const struct bsdf *b = c->b;
    double u = sampler_next(s, DIM_DISCRETE);
    double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS);
    bool glossy = u < 1 - b->diffuse_ratio;
    vec3 wo;
    if (glossy) {
        double ct = pow(u1, 1 / (b->exponent + 1)), st = sqrt(fmax(0.0, 1 - ct * ct)), sn, cs;
        sincos_turns(u2, &sn, &cs);
        frame lobe = frame_from_normal(smooth_reflect(wi));
        wo = frame_to_world(&lobe, v3(st * cs, st * sn, ct));
    } else {
        wo = warp_cosine_hemisphere(u1, u2);
    }
    if (wo.z <= 0) return false;
    double pdf = phong_pdf_up(b, wi, wo);
    if (!(pdf > 0)) return false;
    out->wo = wo;
    out->pdf = pdf;
    out->weight = vscale(phong_f(c, wi, wo), wo.z / pdf);
    out->delta = false;
    out->lobe = glossy ? PHONG_LOBE_GLOSSY : PHONG_LOBE_DIFFUSE;
    return true;
}

static rgb phong_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    (void)mode;
    if (wi.z <= 0 || wo.z <= 0) return v3s(0);
    return phong_f(c, wi, wo);
}

static double phong_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    if (wi.z <= 0 || wo.z <= 0) return 0;
    return phong_pdf_up(c->b, wi, wo);
}

static bool phong_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    if (wi.z <= 0 || wo.z <= 0) return false;
    const struct bsdf *b = c->b;
    double d = b->diffuse_ratio;
    vec3 r = smooth_reflect(wi);
    double pg = (1 - d) * glossy_pdf(b, vdot(r, wo)), pd = d * wo.z * INV_PI;
    if (!(pg + pd > 0)) return false;
    bool glossy = sampler_fresh(w) * (pg + pd) < pg;
    double u1, u2;
    if (glossy) {
        frame lobe = frame_from_normal(r);
        vec3 l = frame_to_local(&lobe, wo);
        u1 = clampd(pow(fmax(l.z, 0.0), b->exponent + 1), 0.0, 1.0);
        u2 = warp_phi(l.x, l.y) / (2 * M_PI);
        if (u2 >= 1) u2 -= 1;
    } else {
        warp_cosine_hemisphere_invert(wo, &u1, &u2);
    }
    sampler_put(w, DIM_DISCRETE,
                glossy ? invert_discrete(0.0, 1 - d, sampler_fresh(w)) : invert_discrete(1 - d, 1.0, sampler_fresh(w)));
    sampler_put(w, DIM_CONTINUOUS, u1);
    sampler_put(w, DIM_CONTINUOUS, u2);
    return true;
}

const struct bsdf_ops bsdf_phong_ops = {
    .dims = 3,
    .sample = phong_sample,
    .eval = phong_eval,
    .pdf = phong_pdf,
    .invert = phong_invert,
    .transmissive = false,
    .delta_only = false,
};
