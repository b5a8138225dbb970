/* The camera ray through a pixel's centre and its first hit: what the per-pixel masks of the
 * figures classify (Fig. 5.5's edges, the MMLT paper's glossy surfaces). */
#ifndef PRIMARY_HIT_H
#define PRIMARY_HIT_H

#include "scene/accel.h"
#include "scene/scene.h"
#include <stdbool.h>

/* Whether the ray through the centre of pixel (x, y) of the scene's camera hits a surface; its hit
 * into *h when it does. */
bool primary_hit(const struct scene *sc, int x, int y, struct hit *h);

#endif
