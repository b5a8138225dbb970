/* Warps from the unit square to sampling domains, each with its pdf and exact inverse
 * (thesis §5.1: every sample(u) -> x has invert(x) -> u). */
#ifndef WARP_H
#define WARP_H

#include "base/vecmath.h"

/* Cosine-weighted hemisphere around +z: polar map r = sqrt(u1), phi = 2 pi u2. */
vec3 warp_cosine_hemisphere(double u1, double u2);
double warp_cosine_hemisphere_pdf(vec3 d);
void warp_cosine_hemisphere_invert(vec3 d, double *u1, double *u2);

vec3 warp_uniform_sphere(double u1, double u2);
double warp_uniform_sphere_pdf(void);
void warp_uniform_sphere_invert(vec3 d, double *u1, double *u2);

/* Uniform over the spherical cap of directions within acos(cos_max) of +z (cos_max < 1):
 * 1 - z = u1 (1 - cos_max), phi = 2 pi u2. The inverse reads 1 - z as (x^2 + y^2) / (1 + z), which
 * keeps its precision for narrow caps. */
vec3 warp_uniform_cap(double u1, double u2, double cos_max);
double warp_uniform_cap_pdf(double cos_max);
void warp_uniform_cap_invert(vec3 d, double cos_max, double *u1, double *u2);

/* Uniform disk of radius 1 in the xy plane: r = sqrt(u1), phi = 2 pi u2. */
void warp_disk(double u1, double u2, double *x, double *y);
void warp_disk_invert(double x, double y, double *u1, double *u2);

/* Uniform triangle: barycentrics (b1, b2) of vertices 1 and 2, by the square-root map. */
void warp_triangle(double u1, double u2, double *b1, double *b2);
void warp_triangle_invert(double b1, double b2, double *u1, double *u2);

/* Angle phi in [0, 2pi) of (x, y). */
double warp_phi(double x, double y);

#endif
