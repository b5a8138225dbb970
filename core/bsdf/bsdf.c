/* BSDF dispatch and derived parameters. */
#include "bsdf/bsdf.h"
#include "bsdf/fresnel.h"

const struct bsdf_ops *const bsdf_ops_table[BSDF_ROUGH_PLASTIC + 1] = {
    [BSDF_NULL] = NULL,
    [BSDF_LAMBERT] = &bsdf_lambert_ops,
    [BSDF_MIRROR] = &bsdf_conductor_ops, /* the conductor's lobe with reflectance 1 */
    [BSDF_CONDUCTOR] = &bsdf_conductor_ops,
    [BSDF_ROUGH_CONDUCTOR] = &bsdf_rough_conductor_ops,
    [BSDF_DIELECTRIC] = &bsdf_dielectric_ops,
    [BSDF_ROUGH_DIELECTRIC] = &bsdf_rough_dielectric_ops,
    [BSDF_PLASTIC] = &bsdf_plastic_ops,
    [BSDF_ROUGH_PLASTIC] = &bsdf_rough_plastic_ops,
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
}
