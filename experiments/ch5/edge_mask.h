/* Which pixels lie near a geometric edge or a facet boundary, from the camera's primary hits
 * (Figure 5.5's table). */
#ifndef EDGE_MASK_H
#define EDGE_MASK_H

#include "scene/scene.h"
#include <stdbool.h>

/* mask[y * w + x] = true within `radius` pixels (Chebyshev) of a boundary between two neighbouring
 * pixel centres that see: a hit and a miss; different primitives; depths differing by more than
 * 5 % (a silhouette of an object in front of itself); or, on a flat-shaded mesh, geometric normals
 * differing by more than 2 degrees (a facet boundary; smooth-shaded meshes have none). Returns a
 * malloc'd array of the camera's width * height. */
bool *edge_mask(const struct scene *sc, int radius);

#endif
