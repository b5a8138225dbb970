/* Transparency (Tungsten's TransparencyBsdf with a constant opacity alpha): with probability
 * alpha the base BSDF scatters, otherwise the ray goes straight on (wo = -wi), a delta lobe of
 * throughput 1 - alpha.
 *   f = alpha f_base,  pdf = alpha pdf_base (continuous lobes; the pass-through is a delta).
 * Tungsten traces the pass-through as a "forward" lobe that shadow rays cross and BDPT leaves out
 * of the path; here it is an ordinary delta vertex (unbiased; connections through it are blocked).
 * Numbers: one discrete (u < alpha -> base), then the base's dims (padding on the pass-through).
 * Inverse: the pass-through takes wo = -wi unless the base has a delta lobe there too (then in
 * proportion to the discrete probabilities, 1 - alpha against alpha p_base). The frame is flipped
 * as the base needs (transmissive = the base's), as Tungsten does: forward lobes do not count. */
#include "bsdf/bsdf_nested.h"
#include "bsdf/bsdf_smooth.h"

static bool tr_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                      struct bsdf_sample *out)
{
    const struct bsdf *b = c->b;
    int end = s->offset + b->dims;
    double u = sampler_next(s, DIM_DISCRETE);
    if (u < b->alpha) {
        struct bsdf_ctx base = bsdf_child_ctx(c, 0);
        if (!bsdf_sample(&base, wi, s, mode, out)) return false;
        nested_pad_next(s, end);
        out->pdf *= b->alpha; /* the weight keeps the base's: alpha cancels */
        out->lobe = NESTED_LOBE(0, out->lobe);
        return true;
    }
    nested_pad_next(s, end);
    out->wo = vneg(wi);
    out->pdf = 1 - b->alpha;
    out->weight = v3s(1);
    out->delta = true;
    out->lobe = 0;
    return true;
}

static rgb tr_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    struct bsdf_ctx base = bsdf_child_ctx(c, 0);
    return vscale(bsdf_eval(&base, wi, wo, mode), c->b->alpha);
}

static double tr_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    struct bsdf_ctx base = bsdf_child_ctx(c, 0);
    return c->b->alpha * bsdf_pdf(&base, wi, wo);
}

static bool tr_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    const struct bsdf *b = c->b;
    int end = w->offset + b->dims;
    struct nested_probe pr = {0};
    double dw[2] = {0, 0}, cw[2] = {0, 0};
    if (b->alpha < 1 && smooth_same_dir(wo, vneg(wi))) dw[0] = 1 - b->alpha;
    if (b->alpha > 0) {
        struct bsdf_ctx base = bsdf_child_ctx(c, 0);
        nested_probe(&base, wi, wo, w, &pr);
        if (pr.ok && pr.delta)
            dw[1] = b->alpha * pr.p_delta;
        else if (pr.ok)
            cw[1] = b->alpha * bsdf_pdf(&base, wi, wo);
    }
    int k = nested_pick(w, 2, dw, cw);
    if (k < 0) return false;
    if (k == 0) {
        sampler_put(w, DIM_DISCRETE, invert_discrete(b->alpha, 1, sampler_fresh(w)));
    } else {
        sampler_put(w, DIM_DISCRETE, invert_discrete(0, b->alpha, sampler_fresh(w)));
        nested_put(w, &pr);
    }
    nested_pad_put(w, end);
    return true;
}

static void tr_prepare(struct bsdf *b)
{
    const struct bsdf *base = b->child[0];
    b->dims = 1 + base->dims;
    b->transmissive = base->transmissive;
    b->delta_only = base->delta_only;
    b->refracts = base->refracts;
    b->refract_ior = base->refract_ior;
    b->pass_through = true;
}

const struct bsdf_ops bsdf_transparency_ops = {
    .dims = 1,
    .sample = tr_sample,
    .eval = tr_eval,
    .pdf = tr_pdf,
    .invert = tr_invert,
    .prepare = tr_prepare,
};
