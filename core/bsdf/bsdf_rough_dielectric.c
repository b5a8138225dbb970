/* Rough dielectric interface: microfacet reflection and refraction (Walter et al. 2007), after
 * Tungsten's RoughDielectricBsdf.cpp. wi.z < 0 means wi is inside (index ior); outside is 1.
 * eta_i / eta_o are the indices on wi's / wo's side; F = Fresnel at wi.m.
 *
 *   reflection  f = F D G / (4 |wi.z| |wo.z|),                     m = sign(wi.z) normalize(wi + wo)
 *   refraction  f = (1 - F) D G |wi.m| |wo.m| eta_o^2 / ((eta_i wi.m + eta_o wo.m)^2 |wi.z| |wo.z|)
 *               m = -(eta_i wi + eta_o wo), oriented to m.z > 0            (Walter Eq. 16, 21)
 * That refraction f is the importance-mode BSDF; TRANSPORT_RADIANCE multiplies it by
 * (eta_i / eta_o)^2, so f_rad(wi, wo) = f_imp(wo, wi) (Veach's generalized reciprocity).
 *
 * Sampling (dims 3): one discrete number ud, then two continuous (u1, u2) -> m ~ D_s(m) m.z where
 * D_s uses Tungsten's widened sampling roughness (1.2 - 0.2 sqrt|wi.z|) alpha. Reflect if
 * ud < F(wi.m) (interval [0, F)), else refract ([F, 1)); with enable_refraction false always
 * reflect (ud is drawn and ignored, interval [0, 1)). Sampling fails when m is back-facing
 * ((wi.m) wi.z <= 0) or wo ends on the wrong side.
 *   pdf: reflection D_s(m) m.z / (4 |wo.m|) * P_R;
 *        refraction D_s(m) m.z eta_o^2 |wo.m| / (eta_i wi.m + eta_o wo.m)^2 * (1 - F)   (Walter Eq. 14, 17)
 * with P_R = F (or 1 without refraction). Lobes: 0 = reflection, 1 = refraction.
 * Inverse: m from the half vector, (u1, u2) = mf_invert(m), ud uniform in the outcome's interval. */
#include "bsdf/bsdf.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"

/* Everything about the pair (wi, wo) that eval, pdf and invert share. */
struct rd_geom {
    bool reflect;
    vec3 m;
    double eta_i, eta_o, wim, wom, F;
};

/* Fresnel at the microfacet, wi on the (wi.z) side of the interface. */
static double rd_fresnel(const struct bsdf *b, double wiz, double wim)
{
    double ct;
    return fresnel_dielectric(fabs(wim), wiz > 0 ? b->ior : 1 / b->ior, &ct);
}

/* False when (wi, wo) cannot come from the lobes (degenerate, wrong sides, lobe disabled). */
static bool rd_geometry(const struct bsdf *b, vec3 wi, vec3 wo, struct rd_geom *g)
{
    if (wi.z == 0 || wo.z == 0) return false;
    g->reflect = wi.z * wo.z > 0;
    if (!g->reflect && !b->enable_refraction) return false;
    g->eta_i = wi.z > 0 ? 1 : b->ior;
    g->eta_o = g->reflect ? g->eta_i : (wo.z > 0 ? 1 : b->ior);
    bool ok = g->reflect ? mf_half_reflect(wi, wo, &g->m) : mf_half_refract(wi, wo, g->eta_i, g->eta_o, &g->m);
    if (!ok) return false;
    g->wim = vdot(wi, g->m);
    g->wom = vdot(wo, g->m);
    /* m must face wi and wo from their own sides of the macro surface */
    if (g->wim * wi.z <= 0 || g->wom * wo.z <= 0) return false;
    g->F = rd_fresnel(b, wi.z, g->wim);
    return true;
}

/* Jacobian dm -> dwo: 1 / (4 |wo.m|) for reflection, eta_o^2 |wo.m| / (eta_i wi.m + eta_o wo.m)^2. */
static double rd_jacobian(const struct rd_geom *g)
{
    if (g->reflect) return 1 / (4 * fabs(g->wom));
    return sqr(g->eta_o) * fabs(g->wom) / sqr(g->eta_i * g->wim + g->eta_o * g->wom);
}

static double rd_lobe_prob(const struct bsdf *b, const struct rd_geom *g)
{
    if (!b->enable_refraction) return 1;
    return g->reflect ? g->F : 1 - g->F;
}

static double rd_radiance_scale(const struct rd_geom *g, enum transport mode)
{
    return (!g->reflect && mode == TRANSPORT_RADIANCE) ? sqr(g->eta_i / g->eta_o) : 1;
}

static bool rd_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                      struct bsdf_sample *out)
{
    const struct bsdf *b = c->b;
    double ud = sampler_next(s, DIM_DISCRETE);
    double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS);
    if (wi.z == 0) return false;
    double alpha = mf_alpha(c->roughness), salpha = mf_sample_alpha(c->roughness, wi.z);
    vec3 m = mf_sample(b->dist, salpha, u1, u2);
    double wim = vdot(wi, m);
    if (wim * wi.z <= 0) return false;
    double pm = mf_pdf(b->dist, salpha, m);
    if (!(pm > 0)) return false;

    struct rd_geom g;
    g.m = m;
    g.wim = wim;
    g.eta_i = wi.z > 0 ? 1 : b->ior;
    double ct;
    g.F = fresnel_dielectric(fabs(wim), wi.z > 0 ? b->ior : 1 / b->ior, &ct);
    g.reflect = !b->enable_refraction || ud < g.F;
    vec3 wo;
    if (g.reflect) {
        g.eta_o = g.eta_i;
        wo = mf_reflect(wi, m);
    } else {
        g.eta_o = wi.z > 0 ? b->ior : 1;
        /* refraction about n' = m oriented toward wi: wo = -eta wi + (eta cos_i - cos_t) n' */
        double eta = g.eta_i / g.eta_o, sgn = wim > 0 ? 1 : -1;
        wo = vadd(vscale(wi, -eta), vscale(m, sgn * (eta * fabs(wim) - ct)));
    }
    if (wo.z * wi.z * (g.reflect ? 1 : -1) <= 0) return false;
    g.wom = vdot(wo, m);
    if (g.wom * wo.z <= 0) return false;
    double pdf = pm * rd_jacobian(&g) * rd_lobe_prob(b, &g);
    if (!(pdf > 0) || !isfinite(pdf)) return false;
    /* f |wo.z| / pdf = D G |wi.m| / (|wi.z| D_s m.z) * (lobe factor / lobe probability) */
    double fr = g.reflect ? (b->enable_refraction ? 1 : g.F) : rd_radiance_scale(&g, mode);
    double G = mf_G(b->dist, alpha, wi, wo, m), D = mf_D(b->dist, alpha, m);
    out->wo = wo;
    out->pdf = pdf;
    out->weight = v3s(fr * D * G * fabs(wim) / (fabs(wi.z) * pm));
    out->delta = false;
    out->lobe = g.reflect ? 0 : 1;
    return true;
}

static rgb rd_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    const struct bsdf *b = c->b;
    struct rd_geom g;
    if (!rd_geometry(b, wi, wo, &g)) return v3s(0);
    double alpha = mf_alpha(c->roughness);
    double DG = mf_D(b->dist, alpha, g.m) * mf_G(b->dist, alpha, wi, wo, g.m);
    double f;
    if (g.reflect)
        f = g.F * DG / (4 * fabs(wi.z * wo.z));
    else
        f = (1 - g.F) * DG * fabs(g.wim * g.wom) * sqr(g.eta_o) /
            (sqr(g.eta_i * g.wim + g.eta_o * g.wom) * fabs(wi.z * wo.z)) * rd_radiance_scale(&g, mode);
    return v3s(f);
}

static double rd_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    const struct bsdf *b = c->b;
    struct rd_geom g;
    if (!rd_geometry(b, wi, wo, &g)) return 0;
    double salpha = mf_sample_alpha(c->roughness, wi.z);
    return mf_pdf(b->dist, salpha, g.m) * rd_jacobian(&g) * rd_lobe_prob(b, &g);
}

static bool rd_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    const struct bsdf *b = c->b;
    struct rd_geom g;
    double u1, u2;
    if (!rd_geometry(b, wi, wo, &g) || !(rd_lobe_prob(b, &g) > 0)) return false;
    if (!mf_invert(b->dist, mf_sample_alpha(c->roughness, wi.z), g.m, &u1, &u2)) return false;
    double lo = 0, hi = 1;
    if (b->enable_refraction) {
        if (g.reflect)
            hi = g.F;
        else
            lo = g.F;
    }
    sampler_put(w, DIM_DISCRETE, invert_discrete(lo, hi, sampler_fresh(w)));
    sampler_put(w, DIM_CONTINUOUS, u1);
    sampler_put(w, DIM_CONTINUOUS, u2);
    return true;
}

const struct bsdf_ops bsdf_rough_dielectric_ops = {
    .dims = 3,
    .sample = rd_sample,
    .eval = rd_eval,
    .pdf = rd_pdf,
    .invert = rd_invert,
    .transmissive = true,
    .delta_only = false,
};
