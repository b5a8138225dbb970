/* Fresnel reflectance for dielectric and conductor interfaces (unpolarised). */
#ifndef FRESNEL_H
#define FRESNEL_H

#include "base/vecmath.h"

/* Dielectric reflectance for cos_i >= 0 on the side of relative index eta = eta_t / eta_i;
 * sets *cos_t (>= 0) for the refracted ray; returns 1 on total internal reflection. */
double fresnel_dielectric(double cos_i, double eta, double *cos_t);
/* Conductor reflectance per channel for cos_i in [0, 1]. */
rgb fresnel_conductor(double cos_i, rgb eta, rgb k);

#endif
