/* Beckmann and GGX microfacet distributions with an invertible normal sampler (see microfacet.h). */
#include "bsdf/microfacet.h"
#include "sampling/warp.h"

/* tan^2 theta of a direction, computed from the tangential part (accurate near the pole). */
static double tan2_theta(vec3 m) { return (m.x * m.x + m.y * m.y) / (m.z * m.z); }

double mf_D(enum mf_dist dist, double alpha, vec3 m)
{
    if (m.z <= 0) return 0;
    double a2 = alpha * alpha, t2 = tan2_theta(m), c2 = m.z * m.z, c4 = c2 * c2;
    if (!isfinite(t2)) return 0;
    if (dist == MF_BECKMANN) return exp(-t2 / a2) / (M_PI * a2 * c4);
    return a2 / (M_PI * c4 * sqr(a2 + t2));
}

double mf_G1(enum mf_dist dist, double alpha, vec3 v, vec3 m)
{
    if (vdot(v, m) * v.z <= 0) return 0;
    double t2 = tan2_theta(v);
    if (dist == MF_BECKMANN) {
        /* Walter Eq. 27: rational fit of 1 / (1 + Lambda(a)), a = 1 / (alpha tan theta); within
         * 0.3 % of the exact Smith term, overshoots 1 by <= 6e-5 just below a = 1.6. Kept as is
         * to match Tungsten's images. */
        double a = 1.0 / (alpha * sqrt(t2));
        if (a >= 1.6) return 1;
        return (3.535 * a + 2.181 * a * a) / (1 + 2.276 * a + 2.577 * a * a);
    }
    return 2 / (1 + sqrt(1 + alpha * alpha * t2));
}

vec3 mf_sample(enum mf_dist dist, double alpha, double u1, double u2)
{
    double a2 = alpha * alpha;
    double t2 = dist == MF_BECKMANN ? -a2 * log1p(-u1) : a2 * u1 / (1 - u1);
    double c = 1 / sqrt(1 + t2), s = sqrt(t2) * c, sn, cs;
    sincos_turns(u2, &sn, &cs);
    return v3(s * cs, s * sn, c);
}

bool mf_invert(enum mf_dist dist, double alpha, vec3 m, double *u1, double *u2)
{
    if (!(m.z > 0)) return false;
    double a2 = alpha * alpha, t2 = tan2_theta(m);
    double u = dist == MF_BECKMANN ? -expm1(-t2 / a2) : t2 / (a2 + t2);
    if (!(u >= 0 && u < 1)) return false;
    double v = warp_phi(m.x, m.y) / (2 * M_PI);
    if (v >= 1) v = 0; /* phi just below 2 pi rounds to 1 */
    *u1 = u;
    *u2 = v;
    return true;
}

static bool orient_unit(vec3 h, vec3 *m)
{
    double l = vlen(h);
    if (!(l > 0) || !isfinite(l) || h.z == 0) return false;
    h = vscale(h, 1 / l);
    *m = h.z < 0 ? vneg(h) : h;
    return m->z > 0;
}

bool mf_half_reflect(vec3 wi, vec3 wo, vec3 *m) { return orient_unit(vadd(wi, wo), m); }

bool mf_half_refract(vec3 wi, vec3 wo, double eta_i, double eta_o, vec3 *m)
{
    return orient_unit(vneg(vadd(vscale(wi, eta_i), vscale(wo, eta_o))), m);
}
