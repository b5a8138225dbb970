/* Mixed (Tungsten's MixedBsdf): a blend of bsdf0 and bsdf1 with weight r of bsdf0, r the constant
 * ratio or its scalar texture at the hit (Tungsten's REQUEST_AVERAGE: texture_load_average), tinted by
 * the mixed BSDF's own albedo:
 *   f = albedo (r f0 + (1 - r) f1),  pdf = r pdf0 + (1 - r) pdf1 (continuous lobes).
 * Numbers: one discrete (u < r -> bsdf0), then the chosen child's numbers, padded to 1 +
 * max(dims0, dims1). A continuous sample reports the blend's pdf and weight f |wo.z| / pdf (one-
 * sample MIS over the two children, as Tungsten); a delta sample keeps its lobe: pdf = r p_delta
 * (or (1 - r) p_delta), weight = albedo times the child's. (Tungsten blends a delta sample with the
 * other child's finite eval and pdf, mixing a Dirac with a density; not reproduced.)
 * Inverse: a child with a delta lobe at wo takes it (both: in proportion to r p0 and (1 - r) p1);
 * otherwise the child is picked in proportion to r pdf0 : (1 - r) pdf1 (thesis Eq. 5.7), u is
 * uniform in its interval and the child's inverse gives the rest. */
#include "bsdf/bsdf_nested.h"

double mixed_ratio(const struct bsdf_ctx *c)
{
    const struct bsdf *b = c->b;
    double r = b->ratio;
    if (b->ratio_tex) {
        r = texture_lookup(b->ratio_tex, c->uv[0], c->uv[1]).x; /* scalar: the same in every channel */
    }
    return clampd(r, 0, 1);
}

static rgb mx_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    double r = mixed_ratio(c);
    struct bsdf_ctx c0 = bsdf_child_ctx(c, 0), c1 = bsdf_child_ctx(c, 1);
    rgb f = v3s(0);
    if (r > 0) f = vscale(bsdf_eval(&c0, wi, wo, mode), r);
    if (r < 1) f = vadd(f, vscale(bsdf_eval(&c1, wi, wo, mode), 1 - r));
    return vmul(c->albedo, f);
}

static double mx_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    double r = mixed_ratio(c), p = 0;
    struct bsdf_ctx c0 = bsdf_child_ctx(c, 0), c1 = bsdf_child_ctx(c, 1);
    if (r > 0) p += r * bsdf_pdf(&c0, wi, wo);
    if (r < 1) p += (1 - r) * bsdf_pdf(&c1, wi, wo);
    return p;
}

static bool mx_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                      struct bsdf_sample *out)
{
    int end = s->offset + c->b->dims;
    double r = mixed_ratio(c);
    int k = sampler_next(s, DIM_DISCRETE) < r ? 0 : 1;
    struct bsdf_ctx ck = bsdf_child_ctx(c, k);
    if (!bsdf_sample(&ck, wi, s, mode, out)) return false;
    nested_pad_next(s, end);
    out->lobe = NESTED_LOBE(k, out->lobe);
    if (out->delta) {
        out->pdf *= k == 0 ? r : 1 - r;
        out->weight = vmul(c->albedo, out->weight);
        return true;
    }
    double pdf = mx_pdf(c, wi, out->wo);
    if (!(pdf > 0) || !isfinite(pdf)) return false;
    out->pdf = pdf;
    out->weight = vscale(mx_eval(c, wi, out->wo, mode), fabs(out->wo.z) / pdf);
    return true;
}

static bool mx_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    int end = w->offset + c->b->dims;
    double r = mixed_ratio(c), pk[2] = {r, 1 - r}, dw[2] = {0, 0}, cw[2] = {0, 0};
    struct nested_probe pr[2] = {{0}};
    for (int k = 0; k < 2; k++) {
        if (!(pk[k] > 0)) continue;
        struct bsdf_ctx ck = bsdf_child_ctx(c, k);
        nested_probe(&ck, wi, wo, w, &pr[k]);
        if (pr[k].ok && pr[k].delta)
            dw[k] = pk[k] * pr[k].p_delta;
        else if (pr[k].ok)
            cw[k] = pk[k] * bsdf_pdf(&ck, wi, wo);
    }
    int k = nested_pick(w, 2, dw, cw);
    if (k < 0) return false;
    sampler_put(w, DIM_DISCRETE,
                k == 0 ? invert_discrete(0, r, sampler_fresh(w)) : invert_discrete(r, 1, sampler_fresh(w)));
    nested_put(w, &pr[k]);
    nested_pad_put(w, end);
    return true;
}

static void mx_prepare(struct bsdf *b)
{
    const struct bsdf *c0 = b->child[0], *c1 = b->child[1];
    b->dims = 1 + (c0->dims > c1->dims ? c0->dims : c1->dims);
    b->transmissive = c0->transmissive || c1->transmissive;
    b->delta_only = c0->delta_only && c1->delta_only;
    b->needs_uv |= b->ratio_tex != NULL;
    b->refracts = c0->refracts || c1->refracts;
    b->refract_ior = c0->refracts ? c0->refract_ior : c1->refract_ior;
    b->pass_through = c0->pass_through || c1->pass_through;
}

const struct bsdf_ops bsdf_mixed_ops = {
    .dims = 1,
    .sample = mx_sample,
    .eval = mx_eval,
    .pdf = mx_pdf,
    .invert = mx_invert,
    .prepare = mx_prepare,
};
