/* Shared pieces of the smooth (delta and Lambertian) BSDF families: lobe indices reported in
 * bsdf_sample.lobe, the ideal reflection/refraction directions, and the tolerance with which
 * invert() recognises a delta direction given in path space.
 *
 * Lobe indices:   lambert  0 diffuse
 *                 mirror   0 reflection           conductor 0 reflection
 *                 dielectric 0 reflection, 1 refraction
 *                 plastic  0 coat (delta reflection), 1 diffuse substrate
 * Dimensions:     lambert 2 (continuous), mirror 0, conductor 0, dielectric 1 (discrete),
 *                 plastic 3 (1 discrete, then 2 continuous; consumed on both lobes). */
#ifndef BSDF_SMOOTH_H
#define BSDF_SMOOTH_H

#include "base/vecmath.h"

enum { LAMBERT_LOBE_DIFFUSE = 0 };
enum { CONDUCTOR_LOBE_REFLECT = 0 }; /* conductor and mirror */
enum { DIELECTRIC_LOBE_REFLECT = 0, DIELECTRIC_LOBE_REFRACT = 1 };
enum { PLASTIC_LOBE_COAT = 0, PLASTIC_LOBE_DIFFUSE = 1 };

/* A given wo matches a delta direction when it lies within this distance of it. In a path, wo
 * comes from two hit points that Embree found in single precision (~2e-7 of the scene's size each),
 * so over a segment of length L it is off by ~2e-7 / L: 1e-7 failed 15 % of all camera walks in
 * scenes/materials (its mirror, gold and glass spheres); 1e-4 covers segments down to ~0.002. */
#define SMOOTH_DELTA_TOL 1e-4

/* Mirror reflection about the local normal (+z). */
static inline vec3 smooth_reflect(vec3 wi) { return v3(-wi.x, -wi.y, wi.z); }

/* Refraction of wi through the z = 0 interface, eta = eta_wo_side / eta_wi_side, cos_t >= 0 from
 * fresnel_dielectric(); the result lies on the other side of the interface from wi. */
static inline vec3 smooth_refract(vec3 wi, double eta, double cos_t)
{
    return v3(-wi.x / eta, -wi.y / eta, wi.z < 0 ? cos_t : -cos_t);
}

static inline bool smooth_same_dir(vec3 a, vec3 b) { return vlen(vsub(a, b)) < SMOOTH_DELTA_TOL; }

#endif
