/* Thin sheet (Tungsten's thinsheet): a slab of index ior and the given thickness, thinner than
 * anything the renderer resolves, so light leaves it where it entered. Two delta lobes:
 *   reflection   wo = mirror(wi), weight R (grey, inter-reflections summed: bsdf_leaf.h);
 *   transmission wo = -wi (no change of direction nor of eta: same medium on both sides),
 *                weight T = (1 - R) exp(-sigma_a 2 thickness / cos theta_t).
 * One discrete number picks reflection with probability R / (R + mean T), in proportion to what
 * each lobe carries (Tungsten picks transmission with probability mean T, which differs only when
 * the sheet absorbs). Both sides behave alike (transmissive: never flipped). albedo is not used,
 * as in Tungsten. Tungsten treats the transmission as a "forward" event its shadow rays pass
 * through; here it is an ordinary delta vertex, so connections through a sheet are blocked. */
#include "bsdf/bsdf.h"
#include "bsdf/bsdf_leaf.h"
#include "bsdf/bsdf_smooth.h"

struct thinsheet_optics thinsheet_optics(const struct bsdf *b, double cos_i)
{
    struct thinsheet_optics o = {1, v3s(0)};
    double eta = 1.0 / b->ior, sin_t2 = eta * eta * (1 - cos_i * cos_i);
    if (sin_t2 >= 1) return o; /* ior < 1 beyond the critical angle: everything reflects */
    double cos_t = sqrt(1 - sin_t2);
    double rs = sqr((eta * cos_i - cos_t) / (eta * cos_i + cos_t));
    double rp = sqr((eta * cos_t - cos_i) / (eta * cos_t + cos_i));
    /* one polarisation: T_total = (1 - r)^2 / (1 - r^2) = (1 - r) / (1 + r) */
    o.R = 1 - 0.5 * ((1 - rs) / (1 + rs) + (1 - rp) / (1 + rp));
    double len = 2 * b->thickness / cos_t;
    rgb sa = b->sigma_a;
    o.T = v3((1 - o.R) * exp(-sa.x * len), (1 - o.R) * exp(-sa.y * len), (1 - o.R) * exp(-sa.z * len));
    return o;
}

static double p_reflect(const struct thinsheet_optics *o)
{
    double t = (o->T.x + o->T.y + o->T.z) / 3.0;
    return o->R + t > 0 ? o->R / (o->R + t) : 0;
}

static bool thinsheet_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                             struct bsdf_sample *out)
{
    (void)mode;
    if (wi.z == 0) return false;
    struct thinsheet_optics o = thinsheet_optics(c->b, fabs(wi.z));
    double pr = p_reflect(&o), u = sampler_next(s, DIM_DISCRETE);
    out->delta = true;
    if (u < pr) {
        out->wo = smooth_reflect(wi);
        out->pdf = pr;
        out->weight = v3s(o.R / pr);
        out->lobe = THINSHEET_LOBE_REFLECT;
        return true;
    }
    if (pr >= 1 || !(vmax(o.T) > 0)) return false; /* unreachable unless the sheet is black */
    out->wo = vneg(wi);
    out->pdf = 1 - pr;
    out->weight = vscale(o.T, 1 / (1 - pr));
    out->lobe = THINSHEET_LOBE_TRANSMIT;
    return true;
}

static rgb thinsheet_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    (void)c, (void)wi, (void)wo, (void)mode;
    return v3s(0);
}

static double thinsheet_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    (void)c, (void)wi, (void)wo;
    return 0;
}

static bool thinsheet_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    if (wi.z == 0) return false;
    struct thinsheet_optics o = thinsheet_optics(c->b, fabs(wi.z));
    double pr = p_reflect(&o);
    if (pr > 0 && wo.z * wi.z > 0 && smooth_same_dir(wo, smooth_reflect(wi))) {
        sampler_put(w, DIM_DISCRETE, invert_discrete(0.0, pr, sampler_fresh(w)));
        return true;
    }
    if (pr < 1 && wo.z * wi.z < 0 && smooth_same_dir(wo, vneg(wi))) {
        sampler_put(w, DIM_DISCRETE, invert_discrete(pr, 1.0, sampler_fresh(w)));
        return true;
    }
    return false;
}

/* A mixed BSDF holding a sheet and a dielectric refracts; the sheet's straight lobe must not carry
 * the dielectric's eta^2 in PITP's technique ratio (pitp.c, radiance_factor). */
static void thinsheet_prepare(struct bsdf *b) { b->pass_through = true; }

const struct bsdf_ops bsdf_thinsheet_ops = {
    .dims = 1,
    .sample = thinsheet_sample,
    .eval = thinsheet_eval,
    .pdf = thinsheet_pdf,
    .invert = thinsheet_invert,
    .transmissive = true,
    .delta_only = true,
    .prepare = thinsheet_prepare,
};
