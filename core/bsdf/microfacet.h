/* Microfacet distributions (Beckmann, GGX) for the rough_* BSDFs, in the local frame (z = macro
 * normal): normal distribution D, Smith shadowing G1 / separable G, sampling of a microfacet normal
 * with density D(m) |m.z| from two numbers, and the exact inverse m -> (u1, u2) (thesis §5.1.1).
 *
 * Formulas: Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces"
 * (Eq. 25 Beckmann D, Eq. 27 rational approximation of Beckmann's Smith G1, Eq. 28 sampling;
 * Eq. 33/34 GGX D and G1, Eq. 35 sampling), as Tungsten's Microfacet.hpp uses them.
 *
 * Sampling map: phi = 2 pi u2 and
 *   Beckmann  tan^2 theta = -alpha^2 log(1 - u1)     <=>  u1 = 1 - exp(-tan^2 theta / alpha^2)
 *   GGX       tan^2 theta = alpha^2 u1 / (1 - u1)    <=>  u1 = tan^2 theta / (alpha^2 + tan^2 theta)
 * m always has m.z > 0. */
#ifndef MICROFACET_H
#define MICROFACET_H

#include "base/vecmath.h"
#include "scene/scene.h"

/* Tungsten's roughnessToAlpha floor: alpha below this is raised to it (a model choice, applied to
 * eval, pdf and sample alike, so it changes the material, not the estimator). */
#define MF_MIN_ALPHA 1e-3

static inline double mf_alpha(double roughness) { return maxd(roughness, MF_MIN_ALPHA); }

/* Tungsten widens the roughness used for SAMPLING rough dielectrics (and rough plastic's coat,
 * which reuses that code) to (1.2 - 0.2 sqrt|cos theta_i|) alpha; eval keeps alpha. */
static inline double mf_sample_alpha(double roughness, double cos_wi)
{
    return mf_alpha((1.2 - 0.2 * sqrt(fabs(cos_wi))) * roughness);
}

/* Normal distribution D(m); 0 for m.z <= 0. Normalised: integral of D(m) m.z over the hemisphere = 1. */
double mf_D(enum mf_dist dist, double alpha, vec3 m);
/* Smith monodirectional shadowing G1(v, m); 0 when v is on the back of m relative to the macro
 * surface ((v.m) v.z <= 0). */
double mf_G1(enum mf_dist dist, double alpha, vec3 v, vec3 m);
/* Separable Smith G = G1(wi, m) G1(wo, m). */
static inline double mf_G(enum mf_dist dist, double alpha, vec3 wi, vec3 wo, vec3 m)
{
    return mf_G1(dist, alpha, wi, m) * mf_G1(dist, alpha, wo, m);
}
/* Density of mf_sample over solid angle: D(m) m.z. */
static inline double mf_pdf(enum mf_dist dist, double alpha, vec3 m) { return mf_D(dist, alpha, m) * m.z; }

vec3 mf_sample(enum mf_dist dist, double alpha, double u1, double u2);
/* Exact inverse of mf_sample for a unit m with m.z > 0; false if m is not in its image
 * (m.z <= 0, or so close to the horizon that u1 rounds to 1). */
bool mf_invert(enum mf_dist dist, double alpha, vec3 m, double *u1, double *u2);

/* Half vectors (Walter Eq. 13 and Eq. 16), returned unit with m.z > 0; false when degenerate
 * (zero length or m.z == 0). Reflection: +-normalize(wi + wo); refraction: the generalized half
 * vector -(eta_i wi + eta_o wo), eta_i on wi's side, eta_o on wo's side. */
bool mf_half_reflect(vec3 wi, vec3 wo, vec3 *m);
bool mf_half_refract(vec3 wi, vec3 wo, double eta_i, double eta_o, vec3 *m);

/* Mirror reflection of wi about m. */
static inline vec3 mf_reflect(vec3 wi, vec3 m) { return vsub(vscale(m, 2 * vdot(wi, m)), wi); }

#endif
