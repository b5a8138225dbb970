/* Smooth plastic: a smooth dielectric coat (index ior) over a Lambertian substrate (albedo A),
 * with absorption sigma_a over a layer of the given thickness. Model as Tungsten's PlasticBsdf:
 *   coat:     delta reflection with weight Fi = F(cos wi);
 *   diffuse:  f = (1 - Fi)(1 - Fo) / (ior^2 pi) * A / (1 - A Fdr) * exp(-thickness sigma_a (1/cos wi + 1/cos wo)),
 *             with Fdr = b->diffuse_fresnel (cosine-weighted Fresnel average seen from inside);
 *   P(coat) = Fi / (Fi + T (1 - Fi) mean(A)),  T = exp(-2 thickness avg(sigma_a)): in proportion to
 *             what each lobe reflects (coat_choice_prob, fresnel.h; Tungsten leaves mean(A) out).
 * Numbers: one discrete (u < P(coat) -> coat), then two continuous (cosine hemisphere), consumed
 * on both lobes so the layout is fixed; the coat ignores them and invert() fills them with fresh
 * uniforms (every value reproduces the coat sample: thesis Eq. 5.3). eval/pdf cover the diffuse
 * lobe only. f(wi, wo) is symmetric in wi and wo, so the diffuse part is reciprocal. */
#include "bsdf/bsdf.h"
#include "bsdf/bsdf_smooth.h"
#include "bsdf/fresnel.h"
#include "sampling/warp.h"

static double coat_fresnel(const struct bsdf *b, double cos_out)
{
    double ct;
    return fresnel_dielectric(cos_out, b->ior, &ct);
}

static double p_coat(const struct bsdf_ctx *c, double Fi) { return coat_choice_prob(Fi, c->b->coat_T, c->albedo); }

static rgb diffuse_f(const struct bsdf_ctx *c, vec3 wi, vec3 wo, double Fi)
{
    const struct bsdf *b = c->b;
    double Fo = coat_fresnel(b, wo.z);
    rgb a = c->albedo;
    double s = (1.0 - Fi) * (1.0 - Fo) / (b->ior * b->ior) * INV_PI;
    double fdr = b->diffuse_fresnel;
    rgb f = v3(s * a.x / (1.0 - a.x * fdr), s * a.y / (1.0 - a.y * fdr), s * a.z / (1.0 - a.z * fdr));
    return vmul(f, layer_transmittance(b->sigma_a, b->thickness, wi.z, wo.z));
}

static bool plastic_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                           struct bsdf_sample *out)
{
    (void)mode;
    if (wi.z <= 0) return false;
    double Fi = coat_fresnel(c->b, wi.z), pc = p_coat(c, Fi);
    double u = sampler_next(s, DIM_DISCRETE);
    double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS);
    if (u < pc) {
        out->wo = smooth_reflect(wi);
        out->pdf = pc;
        out->weight = v3s(Fi / pc);
        out->delta = true;
        out->lobe = PLASTIC_LOBE_COAT;
        return true;
    }
    vec3 wo = warp_cosine_hemisphere(u1, u2);
    double pdf = warp_cosine_hemisphere_pdf(wo) * (1.0 - pc);
    if (pdf <= 0) return false;
    out->wo = wo;
    out->pdf = pdf;
    out->weight = vscale(diffuse_f(c, wi, wo, Fi), wo.z / pdf);
    out->delta = false;
    out->lobe = PLASTIC_LOBE_DIFFUSE;
    return true;
}

static rgb plastic_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    (void)mode;
    if (wi.z <= 0 || wo.z <= 0) return v3s(0);
    return diffuse_f(c, wi, wo, coat_fresnel(c->b, wi.z));
}

static double plastic_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    if (wi.z <= 0 || wo.z <= 0) return 0;
    return warp_cosine_hemisphere_pdf(wo) * (1.0 - p_coat(c, coat_fresnel(c->b, wi.z)));
}

static bool plastic_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    if (wi.z <= 0 || wo.z <= 0) return false;
    double pc = p_coat(c, coat_fresnel(c->b, wi.z));
    /* The diffuse lobe reaches the mirror direction with probability zero: the coat takes it. */
    if (pc > 0 && smooth_same_dir(wo, smooth_reflect(wi))) {
        sampler_put(w, DIM_DISCRETE, invert_discrete(0.0, pc, sampler_fresh(w)));
        sampler_put(w, DIM_CONTINUOUS, sampler_fresh(w));
        sampler_put(w, DIM_CONTINUOUS, sampler_fresh(w));
        return true;
    }
    if (pc >= 1) return false;
    double u1, u2;
    warp_cosine_hemisphere_invert(wo, &u1, &u2);
    sampler_put(w, DIM_DISCRETE, invert_discrete(pc, 1.0, sampler_fresh(w)));
    sampler_put(w, DIM_CONTINUOUS, u1);
    sampler_put(w, DIM_CONTINUOUS, u2);
    return true;
}

const struct bsdf_ops bsdf_plastic_ops = {
    .dims = 3,
    .sample = plastic_sample,
    .eval = plastic_eval,
    .pdf = plastic_pdf,
    .invert = plastic_invert,
    .transmissive = false,
    .delta_only = false,
};
