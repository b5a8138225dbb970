/* Shared set-up for the rough BSDF tests (test_bsdf_rough.c, test_bsdf_rough_stat.c): a sampler
 * drawing from a caller's rng, test materials and incident directions. */
#ifndef ROUGH_UTIL_H
#define ROUGH_UTIL_H

#include "base/rng.h"
#include "bsdf/bsdf.h"
#include "bsdf/microfacet.h"
#include "sampler/sampler.h"
#include <stdio.h>
#include <string.h>

/* One test configuration: material plus incident direction and transport mode. */
struct rough_case {
    struct bsdf b;
    struct bsdf_ctx c;
    const struct bsdf_ops *ops;
    vec3 wi;
    enum transport mode;
};

static inline struct bsdf rough_material(enum bsdf_type type, enum mf_dist dist, double alpha)
{
    struct bsdf b;
    memset(&b, 0, sizeof b);
    b.type = type;
    b.dist = dist;
    b.roughness = alpha;
    b.albedo = v3(0.9, 0.6, 0.3);
    b.eta = v3(0.2, 0.92, 1.1); /* Cu-like */
    b.k = v3(3.9, 2.45, 2.14);
    b.ior = 1.5;
    b.enable_refraction = true;
    b.thickness = 1;
    b.sigma_a = v3(0.1, 0.2, 0.4);
    bsdf_prepare(&b);
    return b;
}

/* Must be called after the struct is in its final place (c.b points into it). */
static inline void rough_case_bind(struct rough_case *k)
{
    k->c = bsdf_ctx_at(&k->b, NULL);
    k->ops = bsdf_ops_for(k->b.type);
}

/* Incident direction with the given cos theta (sign picks the side) at azimuth phi. */
static inline vec3 dir_cos(double cos_theta, double phi)
{
    double s = sqrt(fmax(0.0, 1 - cos_theta * cos_theta));
    return v3(s * cos(phi), s * sin(phi), cos_theta);
}

static const double rough_alphas[] = {0.1, 0.3, 0.7};
#define N_ROUGH_ALPHAS 3
/* Incident cosines: near-normal, oblique, shallow and grazing (cos theta = 0.05). */
static const double rough_cos[] = {0.95, 0.6, 0.25, 0.05};
#define N_ROUGH_COS 4
#define MAX_ROUGH_CASES (2 * N_ROUGH_ALPHAS * N_ROUGH_COS * 2)

/* Every configuration of a family: both distributions, rough_alphas, rough_cos; for the rough
 * dielectric also incidence from inside (wi.z < 0). Transport mode alternates so both are covered. */
static inline int rough_cases(enum bsdf_type type, struct rough_case *out)
{
    int n = 0;
    int sides = type == BSDF_ROUGH_DIELECTRIC ? 2 : 1;
    for (int d = 0; d < 2; d++)
        for (int a = 0; a < N_ROUGH_ALPHAS; a++)
            for (int i = 0; i < N_ROUGH_COS; i++)
                for (int side = 0; side < sides; side++) {
                    struct rough_case *k = &out[n];
                    k->b = rough_material(type, d ? MF_GGX : MF_BECKMANN, rough_alphas[a]);
                    k->wi = dir_cos(side ? -rough_cos[i] : rough_cos[i], 0.3 + 1.7 * i + 0.9 * a);
                    k->mode = (n % 2) ? TRANSPORT_IMPORTANCE : TRANSPORT_RADIANCE;
                    rough_case_bind(k);
                    n++;
                }
    return n;
}

static inline const char *rough_case_name(const struct rough_case *k, char *buf, int len)
{
    snprintf(buf, (size_t)len, "type=%d dist=%s alpha=%g wi=(%.3f,%.3f,%.3f) mode=%s refr=%d", (int)k->b.type,
             k->b.dist == MF_GGX ? "ggx" : "beckmann", k->b.roughness, k->wi.x, k->wi.y, k->wi.z,
             k->mode == TRANSPORT_RADIANCE ? "radiance" : "importance", (int)k->b.enable_refraction);
    return buf;
}

static inline double rel_err(double a, double b) { return fabs(a - b) / fmax(fabs(a), fabs(b)); }

#endif
