/* Coats (Tungsten's SmoothCoatBsdf and RoughCoatBsdf): a dielectric layer of index n = ior over
 * any substrate BSDF, with absorption tau = thickness sigma_a (per channel) inside the layer.
 * Light refracts in, scatters at the substrate, refracts out on the same side, so the coat is a
 * reflector (wi.z > 0 and wo.z > 0; a substrate sample below its horizon fails) and the radiance
 * scalings of the two refractions cancel (no transport-mode factor). With eta = 1 / n:
 *   in:   Fi = F(wi.z), wi' = (eta wi.x, eta wi.y, cos_ti) (cos_ti from Snell); likewise wo -> wo'
 *   f_sub = eta^2 (1 - Fi)(1 - Fo) f_s(wi', wo') exp(-tau (1/cos_ti + 1/cos_to))
 *   pdf_sub = pdf_s(wi', wo') eta^2 wo.z / cos_to       (d omega' / d omega, Snell's compression)
 * smooth_coat adds the coat's delta reflection with weight Fi; rough_coat a microfacet reflection
 * (distribution, roughness; Tungsten's RoughDielectricBsdf with refraction off)
 *   f_g = F(wi.h) D(h) G(wi, wo, h) / (4 wi.z wo.z),  pdf_g = D_s(h) h.z / (4 wo.h)
 * with Tungsten's widened sampling roughness D_s (microfacet.h).
 * The coat is chosen with Tungsten's probability P = Fi / (Fi + T (1 - Fi)), T = exp(-2 mean(tau)).
 * eval and pdf are exactly these sums (continuous lobes; P and 1 - P weigh the pdfs). Tungsten's
 * rough coat multiplies a sampled substrate weight by wi.z / cos_ti, which its eval lacks, and
 * blends a delta substrate sample with the coat's density, (f_g cos + w p_s) / (P p_g + (1 - P) p_s);
 * here sample, eval and pdf agree (bsdf-coat's relMSE: scenes/README.md, Nested BSDFs).
 *
 * Numbers: one discrete (u < P -> coat), then smooth_coat: the substrate's dims (padding on the
 * coat's reflection); rough_coat: max(2, substrate dims), the coat's (u1, u2) or the substrate's.
 * A continuous sample reports pdf() and f |wo.z| / pdf (rough_coat: both lobes, one-sample MIS);
 * a delta substrate sample keeps its lobe, pdf (1 - P) p_delta, weight (1 - Fi)(1 - Fo) exp(..)
 * w_s / (1 - P). Inverse: a delta lobe at wo (the coat's mirror direction, a delta substrate's
 * refracted one) takes it, in proportion to the discrete probabilities when both do; otherwise coat
 * and substrate are picked in proportion to their pdf terms (thesis Eq. 5.7). */
#include "bsdf/bsdf_nested.h"
#include "bsdf/bsdf_smooth.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"

/* The layer seen along wi. */
struct coat_in {
    double Fi, cos_ti, P;
    vec3 wi_s; /* wi refracted into the layer, in the substrate's frame */
};

static bool coat_enter(const struct bsdf *b, vec3 wi, struct coat_in *k)
{
    if (wi.z <= 0) return false;
    double eta = 1 / b->ior;
    k->Fi = fresnel_dielectric(wi.z, b->ior, &k->cos_ti);
    k->wi_s = v3(eta * wi.x, eta * wi.y, k->cos_ti);
    double den = k->Fi + b->coat_T * (1 - k->Fi);
    k->P = den > 0 ? k->Fi / den : 1;
    return true;
}

/* The substrate's share of f and of the pdf (without P) at an outside wo; false when wo does not
 * reach the substrate (below the horizon). *wo_s, *cos_to: wo refracted into the layer. */
static bool coat_substrate(const struct bsdf_ctx *c, const struct coat_in *k, vec3 wo, enum transport mode, rgb *f,
                           double *pdf, vec3 *wo_s)
{
    const struct bsdf *b = c->b;
    if (wo.z <= 0 || k->Fi >= 1) return false;
    double eta = 1 / b->ior, cos_to;
    double Fo = fresnel_dielectric(wo.z, b->ior, &cos_to);
    if (Fo >= 1 || !(cos_to > 0)) return false;
    *wo_s = v3(eta * wo.x, eta * wo.y, cos_to);
    struct bsdf_ctx s = bsdf_child_ctx(c, 0);
    if (f) {
        double scale = eta * eta * (1 - k->Fi) * (1 - Fo);
        *f = vmul(vscale(bsdf_eval(&s, k->wi_s, *wo_s, mode), scale),
                  layer_transmittance(b->sigma_a, b->thickness, k->cos_ti, cos_to));
    }
    if (pdf) *pdf = bsdf_pdf(&s, k->wi_s, *wo_s) * eta * eta * wo.z / cos_to;
    return true;
}

/* The substrate's sample, carried out through the coat: wo and the throughput of the whole path
 * through the layer (1 - Fi)(1 - Fo) exp(..) w_s, before the choice probability 1 - P. */
static bool coat_sample_substrate(const struct bsdf_ctx *c, const struct coat_in *k, struct sampler *s,
                                  enum transport mode, struct bsdf_sample *out)
{
    const struct bsdf *b = c->b;
    struct bsdf_ctx sc = bsdf_child_ctx(c, 0);
    struct bsdf_sample bs;
    if (!bsdf_sample(&sc, k->wi_s, s, mode, &bs) || bs.wo.z <= 0) return false;
    double cos_t;
    double Fo = fresnel_dielectric(bs.wo.z, 1 / b->ior, &cos_t);
    if (Fo >= 1) return false; /* total internal reflection: Tungsten drops it too */
    out->wo = v3(bs.wo.x * b->ior, bs.wo.y * b->ior, cos_t);
    out->weight = vmul(vscale(bs.weight, (1 - k->Fi) * (1 - Fo)),
                       layer_transmittance(b->sigma_a, b->thickness, k->cos_ti, bs.wo.z));
    /* a delta keeps its discrete probability; a density takes Snell's compression d omega' / d omega */
    out->pdf = bs.delta ? bs.pdf : bs.pdf * cos_t / (sqr(b->ior) * bs.wo.z);
    out->delta = bs.delta;
    out->lobe = NESTED_LOBE(0, bs.lobe);
    return out->wo.z > 0;
}

static void coat_prepare(struct bsdf *b)
{
    const struct bsdf *s = b->child[0];
    b->dims = 1 + s->dims;
    b->transmissive = false;
    b->delta_only = s->delta_only;
    b->refracts = false; /* in and out on the same side: the eta^2 factors cancel */
    b->refract_ior = 0;
    b->pass_through = false;
}

/* ---- smooth_coat ---- */

static bool sc_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                      struct bsdf_sample *out)
{
    int end = s->offset + c->b->dims;
    double u = sampler_next(s, DIM_DISCRETE);
    struct coat_in k;
    if (!coat_enter(c->b, wi, &k)) return false;
    if (u < k.P) {
        nested_pad_next(s, end);
        out->wo = smooth_reflect(wi);
        out->pdf = k.P;
        out->weight = v3s(k.Fi / k.P);
        out->delta = true;
        out->lobe = 0;
        return true;
    }
    if (!coat_sample_substrate(c, &k, s, mode, out)) return false;
    nested_pad_next(s, end);
    out->pdf *= 1 - k.P;
    out->weight = vscale(out->weight, 1 / (1 - k.P));
    return out->pdf > 0 && vfinite(out->weight);
}

static rgb sc_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    struct coat_in k;
    rgb f;
    vec3 wo_s;
    if (!coat_enter(c->b, wi, &k) || !coat_substrate(c, &k, wo, mode, &f, NULL, &wo_s)) return v3s(0);
    return f;
}

static double sc_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    struct coat_in k;
    double p;
    vec3 wo_s;
    if (!coat_enter(c->b, wi, &k) || !coat_substrate(c, &k, wo, TRANSPORT_RADIANCE, NULL, &p, &wo_s)) return 0;
    return (1 - k.P) * p;
}

/* Inversion's share of the substrate at wo (both coats): its discrete weight *dw when the substrate
 * reaches wo by a delta lobe, else its continuous pdf term *cw; pr keeps the substrate's numbers. */
static void substrate_weight(const struct bsdf_ctx *c, const struct coat_in *k, vec3 wo, struct sampler *w,
                             struct nested_probe *pr, double *dw, double *cw)
{
    double p;
    vec3 wo_s;
    if (!(k->P < 1 && coat_substrate(c, k, wo, TRANSPORT_RADIANCE, NULL, &p, &wo_s))) return;
    struct bsdf_ctx s = bsdf_child_ctx(c, 0);
    nested_probe(&s, k->wi_s, wo_s, w, pr);
    if (pr->ok && pr->delta)
        *dw = (1 - k->P) * pr->p_delta;
    else if (pr->ok)
        *cw = (1 - k->P) * p;
}

static bool sc_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    int end = w->offset + c->b->dims;
    struct coat_in k;
    if (!coat_enter(c->b, wi, &k) || wo.z <= 0) return false;
    double dw[2] = {0, 0}, cw[2] = {0, 0};
    if (k.P > 0 && smooth_same_dir(wo, smooth_reflect(wi))) dw[0] = k.P;
    struct nested_probe pr = {0};
    substrate_weight(c, &k, wo, w, &pr, &dw[1], &cw[1]);
    int pick = nested_pick(w, 2, dw, cw);
    if (pick < 0) return false;
    if (pick == 0) {
        sampler_put(w, DIM_DISCRETE, invert_discrete(0, k.P, sampler_fresh(w)));
    } else {
        sampler_put(w, DIM_DISCRETE, invert_discrete(k.P, 1, sampler_fresh(w)));
        nested_put(w, &pr);
    }
    nested_pad_put(w, end);
    return true;
}

const struct bsdf_ops bsdf_smooth_coat_ops = {
    .dims = 1,
    .sample = sc_sample,
    .eval = sc_eval,
    .pdf = sc_pdf,
    .invert = sc_invert,
    .prepare = coat_prepare,
};

/* ---- rough_coat ---- */

static rgb rc_glossy_f(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    const struct bsdf *b = c->b;
    vec3 h;
    if (wi.z <= 0 || wo.z <= 0 || !mf_half_reflect(wi, wo, &h)) return v3s(0);
    double wih = vdot(wi, h), ct;
    if (wih <= 0) return v3s(0);
    double alpha = mf_alpha(c->roughness);
    double F = fresnel_dielectric(wih, b->ior, &ct);
    return v3s(F * mf_D(b->dist, alpha, h) * mf_G(b->dist, alpha, wi, wo, h) / (4 * wi.z * wo.z));
}

static double rc_glossy_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    vec3 h;
    if (wi.z <= 0 || wo.z <= 0 || !mf_half_reflect(wi, wo, &h) || vdot(wi, h) <= 0) return 0;
    return mf_pdf(c->b->dist, mf_sample_alpha(c->roughness, wi.z), h) / (4 * vdot(wo, h));
}

static rgb rc_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    struct coat_in k;
    if (!coat_enter(c->b, wi, &k) || wo.z <= 0) return v3s(0);
    rgb f = rc_glossy_f(c, wi, wo), fs;
    vec3 wo_s;
    if (coat_substrate(c, &k, wo, mode, &fs, NULL, &wo_s)) f = vadd(f, fs);
    return f;
}

static double rc_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    struct coat_in k;
    if (!coat_enter(c->b, wi, &k) || wo.z <= 0) return 0;
    double p = k.P * rc_glossy_pdf(c, wi, wo), ps;
    vec3 wo_s;
    if (k.P < 1 && coat_substrate(c, &k, wo, TRANSPORT_RADIANCE, NULL, &ps, &wo_s)) p += (1 - k.P) * ps;
    return p;
}

static bool rc_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                      struct bsdf_sample *out)
{
    const struct bsdf *b = c->b;
    int end = s->offset + b->dims;
    double u = sampler_next(s, DIM_DISCRETE);
    struct coat_in k;
    if (!coat_enter(b, wi, &k)) return false;
    if (u < k.P) {
        double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS);
        nested_pad_next(s, end);
        vec3 m = mf_sample(b->dist, mf_sample_alpha(c->roughness, wi.z), u1, u2);
        if (vdot(wi, m) <= 0) return false;
        out->wo = mf_reflect(wi, m);
        out->delta = false;
        out->lobe = 0;
    } else {
        if (!coat_sample_substrate(c, &k, s, mode, out)) return false;
        nested_pad_next(s, end);
        if (out->delta) {
            out->pdf *= 1 - k.P;
            out->weight = vscale(out->weight, 1 / (1 - k.P));
            return out->pdf > 0 && vfinite(out->weight);
        }
    }
    if (out->wo.z <= 0) return false;
    double pdf = rc_pdf(c, wi, out->wo);
    if (!(pdf > 0) || !isfinite(pdf)) return false;
    out->pdf = pdf;
    out->weight = vscale(rc_eval(c, wi, out->wo, mode), out->wo.z / pdf);
    return true;
}

static bool rc_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    const struct bsdf *b = c->b;
    int end = w->offset + b->dims;
    struct coat_in k;
    if (!coat_enter(b, wi, &k) || wo.z <= 0) return false;
    double dw[2] = {0, 0}, cw[2] = {0, 0}, u1 = 0, u2 = 0;
    vec3 h;
    cw[0] = k.P * rc_glossy_pdf(c, wi, wo);
    if (!(cw[0] > 0 && mf_half_reflect(wi, wo, &h) &&
          mf_invert(b->dist, mf_sample_alpha(c->roughness, wi.z), h, &u1, &u2)))
        cw[0] = 0;
    struct nested_probe pr = {0};
    substrate_weight(c, &k, wo, w, &pr, &dw[1], &cw[1]);
    int pick = nested_pick(w, 2, dw, cw);
    if (pick < 0) return false;
    if (pick == 0) {
        sampler_put(w, DIM_DISCRETE, invert_discrete(0, k.P, sampler_fresh(w)));
        sampler_put(w, DIM_CONTINUOUS, u1);
        sampler_put(w, DIM_CONTINUOUS, u2);
    } else {
        sampler_put(w, DIM_DISCRETE, invert_discrete(k.P, 1, sampler_fresh(w)));
        nested_put(w, &pr);
    }
    nested_pad_put(w, end);
    return true;
}

static void rc_prepare(struct bsdf *b)
{
    coat_prepare(b);
    int own = 2; /* the coat's microfacet normal */
    b->dims = 1 + (b->child[0]->dims > own ? b->child[0]->dims : own);
    b->delta_only = false;
}

const struct bsdf_ops bsdf_rough_coat_ops = {
    .dims = 3,
    .sample = rc_sample,
    .eval = rc_eval,
    .pdf = rc_pdf,
    .invert = rc_invert,
    .prepare = rc_prepare,
};
