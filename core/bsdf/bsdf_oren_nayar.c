/* Oren-Nayar rough diffuse reflection as Tungsten's oren_nayar: the full model of Oren and Nayar
 * (1994) with its inter-reflection term, sigma = roughness / sqrt(2) (c->roughness, default 1):
 *   f = (A fr1 + A^2 fr2) / pi,
 *   fr1 = C1 + cos(dphi) C2 tan(beta) + (1 - |cos dphi|) C3 tan((alpha + beta) / 2),
 *   fr2 = 0.17 s / (s + 0.13) (1 - cos(dphi) (2 beta / pi)^2),  s = sigma^2,
 * alpha = max(theta_i, theta_o), beta = min; symmetric in wi and wo, so reciprocal.
 * Sampling as Tungsten's: with probability r = clamp(roughness, 0.01, 1) the uniform hemisphere,
 * else the cosine-weighted one; pdf is the mixture. One discrete number (uniform on [0, r)), then
 * two continuous ones: (cos theta, phi / 2 pi) for the uniform map, the polar disk map for the
 * cosine one. invert picks the map in proportion to its share of the mixture pdf at wo. */
#include "bsdf/bsdf.h"
#include "bsdf/bsdf_leaf.h"
#include "sampling/warp.h"

static double uniform_ratio(const struct bsdf_ctx *c) { return clampd(c->roughness, 0.01, 1.0); }

static double on_pdf(const struct bsdf_ctx *c, vec3 wo)
{
    double r = uniform_ratio(c);
    return r * (0.5 * INV_PI) + (1 - r) * wo.z * INV_PI;
}

static rgb on_f(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    double ti = acos(clampd(wi.z, -1.0, 1.0)), to = acos(clampd(wo.z, -1.0, 1.0));
    double alpha = fmax(ti, to), beta = fmin(ti, to);
    double denom = (wi.x * wi.x + wi.y * wi.y) * (wo.x * wo.x + wo.y * wo.y);
    double cdphi = denom > 0 ? clampd((wi.x * wo.x + wi.y * wo.y) / sqrt(denom), -1.0, 1.0) : 1.0;
    double sigma = c->roughness / sqrt(2.0), s = sigma * sigma;
    double c1 = 1 - 0.5 * s / (s + 0.33);
    double c2 = 0.45 * s / (s + 0.09);
    double b2 = 2 * INV_PI * beta;
    c2 *= cdphi >= 0 ? sin(alpha) : sin(alpha) - b2 * b2 * b2;
    double c3 = 0.125 * (s / (s + 0.09)) * sqr(4 * INV_PI * INV_PI * alpha * beta);
    double fr1 = c1 + cdphi * c2 * tan(beta) + (1 - fabs(cdphi)) * c3 * tan(0.5 * (alpha + beta));
    double fr2 = 0.17 * s / (s + 0.13) * (1 - cdphi * b2 * b2);
    rgb a = c->albedo;
    return vscale(vadd(vscale(a, fr1), vscale(vmul(a, a), fr2)), INV_PI);
}

static bool on_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                      struct bsdf_sample *out)
{
    (void)mode;
    if (wi.z <= 0) return false;
    double u = sampler_next(s, DIM_DISCRETE);
    double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS);
    bool uniform = u < uniform_ratio(c);
    vec3 wo;
    if (uniform) {
        double r = sqrt(fmax(0.0, 1 - u1 * u1)), sn, cs;
        sincos_turns(u2, &sn, &cs);
        wo = v3(r * cs, r * sn, u1);
    } else {
        wo = warp_cosine_hemisphere(u1, u2);
    }
    if (wo.z <= 0) return false;
    double pdf = on_pdf(c, wo);
    out->wo = wo;
    out->pdf = pdf;
    out->weight = vscale(on_f(c, wi, wo), wo.z / pdf);
    out->delta = false;
    out->lobe = uniform ? OREN_NAYAR_LOBE_UNIFORM : OREN_NAYAR_LOBE_COSINE;
    return true;
}

static rgb on_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    (void)mode;
    if (wi.z <= 0 || wo.z <= 0) return v3s(0);
    return on_f(c, wi, wo);
}

static double on_pdf_op(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    if (wi.z <= 0 || wo.z <= 0) return 0;
    return on_pdf(c, wo);
}

static bool on_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    if (wi.z <= 0 || wo.z <= 0) return false;
    double r = uniform_ratio(c), pu = r * (0.5 * INV_PI), pc = (1 - r) * wo.z * INV_PI;
    bool uniform = sampler_fresh(w) * (pu + pc) < pu;
    double u1, u2;
    if (uniform) {
        u1 = wo.z;
        u2 = warp_phi(wo.x, wo.y) / (2 * M_PI);
        if (u2 >= 1) u2 -= 1;
    } else {
        warp_cosine_hemisphere_invert(wo, &u1, &u2);
    }
    sampler_put(w, DIM_DISCRETE,
                uniform ? invert_discrete(0.0, r, sampler_fresh(w)) : invert_discrete(r, 1.0, sampler_fresh(w)));
    sampler_put(w, DIM_CONTINUOUS, u1);
    sampler_put(w, DIM_CONTINUOUS, u2);
    return true;
}

const struct bsdf_ops bsdf_oren_nayar_ops = {
    .dims = 3,
    .sample = on_sample,
    .eval = on_eval,
    .pdf = on_pdf_op,
    .invert = on_invert,
    .transmissive = false,
    .delta_only = false,
};
