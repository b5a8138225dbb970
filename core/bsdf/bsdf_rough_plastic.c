/* Rough plastic: a rough dielectric coat (microfacet reflection only) over an absorbing diffuse
 * base, after Tungsten's RoughPlasticBsdf.cpp. Reflection only, wi.z > 0 (the path code flips the
 * frame); eta = 1 / ior, tau = thickness * sigma_a per channel, Fdr = b->diffuse_fresnel.
 *
 *   f = f_coat + f_base
 *   f_coat = F(wi.h) D(h) G(wi, wo, h) / (4 wi.z wo.z),  h = normalize(wi + wo)   (Walter Eq. 20)
 *   f_base = (1 - F(wi.z)) (1 - F(wo.z)) eta^2 albedo / (1 - albedo Fdr) / pi
 *            * exp(-tau (1 / wi.z + 1 / wo.z))
 *
 * Sampling (dims 3): one discrete number ud, then two continuous (u1, u2). The coat lobe is
 * chosen with probability P_c = F(wi.z) / (F(wi.z) + T (1 - F(wi.z)) mean(albedo)), T =
 * exp(-2 mean(tau)): in proportion to what each lobe reflects (coat_choice_prob, fresnel.h;
 * Tungsten's specularProbability leaves the albedo out, and dark bases then starved the coat).
 * Interval [0, P_c) -> coat: m ~ D_s(m) m.z with Tungsten's widened sampling roughness (its rough plastic reuses the
 * rough dielectric sampler), wo = reflect(wi, m); [P_c, 1) -> base: cosine-weighted hemisphere. Lobes: 0 = coat, 1 =
 * base. pdf = P_c D_s(h) h.z / (4 wo.h) + (1 - P_c) wo.z / pi;   weight = f wo.z / pdf (both lobes). Inverse: both
 * lobes can produce any wo, so the lobe is picked with probability equal to its share of the pdf (thesis Eq. 5.7), then
 * ud is uniform in its interval (Eq. 5.8) and (u1, u2) come from that lobe's inverse map. */
#include "bsdf/bsdf.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"
#include "sampling/warp.h"

static double fr_out(double cos_t, double ior)
{
    double ct;
    return fresnel_dielectric(cos_t, ior, &ct);
}

static double coat_prob(const struct bsdf_ctx *c, double wiz)
{
    const struct bsdf *b = c->b;
    return coat_choice_prob(fr_out(wiz, b->ior), b->coat_T, c->albedo);
}

static rgb rp_f(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    const struct bsdf *b = c->b;
    vec3 h;
    rgb f = v3s(0);
    if (mf_half_reflect(wi, wo, &h)) {
        double alpha = mf_alpha(c->roughness), wih = vdot(wi, h);
        if (wih > 0)
            f = v3s(fr_out(wih, b->ior) * mf_D(b->dist, alpha, h) * mf_G(b->dist, alpha, wi, wo, h) /
                    (4 * wi.z * wo.z));
    }
    double eta = 1 / b->ior, Fi = fr_out(wi.z, b->ior), Fo = fr_out(wo.z, b->ior);
    rgb A = c->albedo;
    rgb base = v3(A.x / (1 - A.x * b->diffuse_fresnel), A.y / (1 - A.y * b->diffuse_fresnel),
                  A.z / (1 - A.z * b->diffuse_fresnel));
    base = vmul(base, layer_transmittance(b->sigma_a, b->thickness, wi.z, wo.z));
    return vadd(f, vscale(base, (1 - Fi) * (1 - Fo) * eta * eta * INV_PI));
}

/* The two pdf terms, each including its lobe probability. */
static void rp_pdfs(const struct bsdf_ctx *c, vec3 wi, vec3 wo, double *p_coat, double *p_base)
{
    const struct bsdf *b = c->b;
    double pc = coat_prob(c, wi.z);
    vec3 h;
    *p_coat = 0;
    if (mf_half_reflect(wi, wo, &h) && vdot(wi, h) > 0)
        *p_coat = pc * mf_pdf(b->dist, mf_sample_alpha(c->roughness, wi.z), h) / (4 * vdot(wo, h));
    *p_base = (1 - pc) * wo.z * INV_PI;
}

static bool rp_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                      struct bsdf_sample *out)
{
    (void)mode;
    const struct bsdf *b = c->b;
    double ud = sampler_next(s, DIM_DISCRETE);
    double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS);
    if (wi.z <= 0) return false;
    vec3 wo;
    int lobe;
    if (ud < coat_prob(c, wi.z)) {
        vec3 m = mf_sample(b->dist, mf_sample_alpha(c->roughness, wi.z), u1, u2);
        if (vdot(wi, m) <= 0) return false;
        wo = mf_reflect(wi, m);
        lobe = 0;
    } else {
        wo = warp_cosine_hemisphere(u1, u2);
        lobe = 1;
    }
    if (wo.z <= 0) return false;
    double pc, pb;
    rp_pdfs(c, wi, wo, &pc, &pb);
    double pdf = pc + pb;
    if (!(pdf > 0) || !isfinite(pdf)) return false;
    out->wo = wo;
    out->pdf = pdf;
    out->weight = vscale(rp_f(c, wi, wo), wo.z / pdf);
    out->delta = false;
    out->lobe = lobe;
    return true;
}

static rgb rp_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    (void)mode;
    if (wi.z <= 0 || wo.z <= 0) return v3s(0);
    return rp_f(c, wi, wo);
}

static double rp_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    if (wi.z <= 0 || wo.z <= 0) return 0;
    double pc, pb;
    rp_pdfs(c, wi, wo, &pc, &pb);
    return pc + pb;
}

static bool rp_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    const struct bsdf *b = c->b;
    if (wi.z <= 0 || wo.z <= 0) return false;
    double pc, pb, u1, u2;
    rp_pdfs(c, wi, wo, &pc, &pb);
    if (!(pc + pb > 0)) return false;
    double P = coat_prob(c, wi.z);
    bool coat = sampler_fresh(w) * (pc + pb) < pc; /* Eq. 5.7: lobe in proportion to its pdf share */
    if (coat) {
        vec3 h;
        if (!mf_half_reflect(wi, wo, &h) || !mf_invert(b->dist, mf_sample_alpha(c->roughness, wi.z), h, &u1, &u2))
            return false;
    } else {
        warp_cosine_hemisphere_invert(wo, &u1, &u2);
    }
    sampler_put(w, DIM_DISCRETE,
                coat ? invert_discrete(0, P, sampler_fresh(w)) : invert_discrete(P, 1, sampler_fresh(w)));
    sampler_put(w, DIM_CONTINUOUS, u1);
    sampler_put(w, DIM_CONTINUOUS, u2);
    return true;
}

const struct bsdf_ops bsdf_rough_plastic_ops = {
    .dims = 3,
    .sample = rp_sample,
    .eval = rp_eval,
    .pdf = rp_pdf,
    .invert = rp_invert,
    .transmissive = false,
    .delta_only = false,
};
