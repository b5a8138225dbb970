/* Which pixels show a glossy surface first: the MMLT paper's Figs. 1 and 6 place original MLT's
 * artifacts "on glossy surfaces", so their statistics are measured there (ch6_runs.c). */
#ifndef GLOSSY_MASK_H
#define GLOSSY_MASK_H

#include "scene/scene.h"
#include <stdbool.h>

/* A BSDF with a rough microfacet or a Phong lobe, itself or nested in it (rough conductor,
 * dielectric, plastic or coat; phong): neither Lambertian nor a perfect mirror or refraction. */
bool bsdf_is_glossy(const struct bsdf *b);
/* mask[y * w + x]: the ray through the centre of pixel (x, y) of the scene's camera first hits a
 * glossy surface (a malloc'd array of width * height); *count: how many do. */
bool *glossy_mask(const struct scene *sc, int *count);

#endif
