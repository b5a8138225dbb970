/* BSDF dispatch and derived parameters. */
#include "bsdf/bsdf.h"
#include "base/util.h"
#include "bsdf/fresnel.h"
#include <float.h>
#include <stdlib.h>

const struct bsdf_ops *const bsdf_ops_table[BSDF_NTYPES] = {
    [BSDF_NULL] = NULL,
    [BSDF_LAMBERT] = &bsdf_lambert_ops,
    [BSDF_MIRROR] = &bsdf_conductor_ops, /* the conductor's lobe with reflectance 1 */
    [BSDF_CONDUCTOR] = &bsdf_conductor_ops,
    [BSDF_ROUGH_CONDUCTOR] = &bsdf_rough_conductor_ops,
    [BSDF_DIELECTRIC] = &bsdf_dielectric_ops,
    [BSDF_ROUGH_DIELECTRIC] = &bsdf_rough_dielectric_ops,
    [BSDF_PLASTIC] = &bsdf_plastic_ops,
    [BSDF_ROUGH_PLASTIC] = &bsdf_rough_plastic_ops,
    /* nested BSDFs */
    [BSDF_TRANSPARENCY] = &bsdf_transparency_ops,
    [BSDF_SMOOTH_COAT] = &bsdf_smooth_coat_ops,
    [BSDF_ROUGH_COAT] = &bsdf_rough_coat_ops,
    [BSDF_MIXED] = &bsdf_mixed_ops,
    [BSDF_THINSHEET] = &bsdf_thinsheet_ops,
    [BSDF_DIFFUSE_TRANSMISSION] = &bsdf_diffuse_transmission_ops,
    [BSDF_OREN_NAYAR] = &bsdf_oren_nayar_ops,
    [BSDF_PHONG] = &bsdf_phong_ops,
};

/* Hemispherical average of the coat's Fresnel reflectance seen from inside (cosine-weighted):
 * the fraction of diffusely scattered light the coat sends back down (plastics). */
static double diffuse_fresnel_inside(double ior)
{
    const int n = 2048; /* midpoint rule in cos^2, smooth integrand: error << 1e-6 */
    double s = 0, ct;
    for (int i = 0; i < n; i++) {
        double c = sqrt((i + 0.5) / n);
        s += fresnel_dielectric(c, 1.0 / ior, &ct);
    }
    return s / n;
}

void bsdf_prepare(struct bsdf *b)
{
    if (b->type == BSDF_PLASTIC || b->type == BSDF_ROUGH_PLASTIC) b->diffuse_fresnel = diffuse_fresnel_inside(b->ior);
    b->coat_T = exp(-2 * b->thickness * (b->sigma_a.x + b->sigma_a.y + b->sigma_a.z) / 3);
    const struct bsdf_ops *ops = bsdf_ops_for(b->type);
    b->dims = ops ? ops->dims : 0;
    b->transmissive = ops && ops->transmissive;
    b->delta_only = ops && ops->delta_only;
    b->needs_uv = b->albedo_tex || b->roughness_tex || b->bump_tex;
    for (int i = 0; i < 2; i++)
        if (b->child[i]) b->needs_uv |= b->child[i]->needs_uv;
    /* nested BSDFs: which BSDFs refract (the radiance-mode eta^2 factor, pitp.c); nested types
     * override these in ops->prepare from their children */
    b->refracts = (b->type == BSDF_DIELECTRIC || b->type == BSDF_ROUGH_DIELECTRIC) && b->enable_refraction;
    b->refract_ior = b->refracts ? b->ior : 0;
    b->pass_through = false;
    if (ops && ops->prepare) ops->prepare(b);
}

/* Post-order over the nesting (acyclic: the loader refuses cycles); done[] marks prepared slots. */
static void prepare_rec(struct bsdf *bs, bool *done, struct bsdf *b)
{
    size_t i = (size_t)(b - bs);
    if (done[i]) return;
    for (int k = 0; k < 2; k++)
        if (b->child[k]) prepare_rec(bs, done, &bs[b->child[k] - bs]);
    bsdf_prepare(b);
    done[i] = true;
}

void bsdf_prepare_all(struct bsdf *bs, int n)
{
    bool *done = xcalloc((size_t)(n > 0 ? n : 1), sizeof *done);
    for (int i = 0; i < n; i++)
        prepare_rec(bs, done, &bs[i]);
    free(done);
}

/* A double beyond float's range converts to the nearest finite float (C leaves the cast undefined
 * there; a mesh may carry any uv). */
static float to_float(double x) { return x > FLT_MAX ? FLT_MAX : x < -FLT_MAX ? -FLT_MAX : (float)x; }

struct bsdf_ctx bsdf_ctx_textured(const struct bsdf *b, const double uv[2])
{
    struct bsdf_ctx c = {.b = b, .albedo = b->albedo, .roughness = b->roughness};
    double u = uv ? uv[0] : 0, v = uv ? uv[1] : 0; /* this BSDF's own lookups in double */
    c.uv[0] = to_float(u);
    c.uv[1] = to_float(v);
    if (b->albedo_tex) c.albedo = texture_lookup(b->albedo_tex, u, v);
    /* textures: Tungsten reads the first channel of the (averaged) roughness texture */
    if (b->roughness_tex) c.roughness = texture_lookup(b->roughness_tex, u, v).x;
    return c;
}
