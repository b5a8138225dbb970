/* Ideal mirror: a single delta lobe in the reflected direction, tinted by albedo (as Tungsten's
 * MirrorBsdf). No numbers are consumed; invert only checks that wo is the reflection. */
#include "bsdf.h"
#include "bsdf_smooth.h"

static bool mirror_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                          struct bsdf_sample *out)
{
    (void)s;
    (void)mode;
    if (wi.z <= 0) return false;
    out->wo = smooth_reflect(wi);
    out->pdf = 1;
    out->weight = c->albedo;
    out->delta = true;
    out->lobe = MIRROR_LOBE_REFLECT;
    return true;
}

static rgb mirror_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    (void)c, (void)wi, (void)wo, (void)mode;
    return v3s(0);
}

static double mirror_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    (void)c, (void)wi, (void)wo;
    return 0;
}

static bool mirror_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    (void)c, (void)w;
    return wi.z > 0 && smooth_same_dir(wo, smooth_reflect(wi));
}

const struct bsdf_ops bsdf_mirror_ops = {
    .dims = 0,
    .sample = mirror_sample,
    .eval = mirror_eval,
    .pdf = mirror_pdf,
    .invert = mirror_invert,
    .transmissive = false,
    .delta_only = true,
};
