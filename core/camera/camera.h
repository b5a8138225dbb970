/* Pinhole camera with a box or tent reconstruction filter.
 * Raster coordinates: x to the right, y downward (row 0 on top), pixel (i, j) = [i, i+1) x [j, j+1).
 * The film is the image grown by the filter's margin m on every side (0 for box; 1 for the tent,
 * whose support reaches one pixel beyond a border pixel's centre): x in [-m, width + m),
 * y in [-m, height + m). The image dims map linearly onto it, x = -m + u_x * film_width.
 * Importance is normalised over the film, We(d) = camera_pdf_dir(d): an image estimate is
 * (film area / N) * sum of filter-weighted splats (image.h) over N camera samples, for every
 * technique. Tungsten's camera does the same for the tent: a pixel, then an offset drawn from the
 * tent, so that both measure pixel j as the tent-weighted integral of radiance around its centre. */
#ifndef CAMERA_H
#define CAMERA_H

#include "sampler/sampler.h"
#include "scene/scene.h"

static inline int camera_margin(const struct camera *c) { return c->filter == FILTER_TENT ? 1 : 0; }
static inline int camera_film_width(const struct camera *c) { return c->width + 2 * camera_margin(c); }
static inline int camera_film_height(const struct camera *c) { return c->height + 2 * camera_margin(c); }
/* Film area in pixels: the N of "film area / N" above when N camera samples cover the film. */
static inline double camera_film_area(const struct camera *c)
{
    return (double)camera_film_width(c) * camera_film_height(c);
}

/* Consumes DIM_IMAGE_X then DIM_IMAGE_Y; returns the unit world direction of the primary ray and,
 * if pdf is not NULL, its camera_pdf_dir (known here without a second projection). */
vec3 camera_sample_dir(const struct camera *c, struct sampler *s, double *px, double *py, double *pdf);
/* Raster position seen along world direction d from the camera, and camera_pdf_dir(d) (returned:
 * 0 if behind or outside the film, then px, py are not set). */
double camera_raster(const struct camera *c, vec3 d, double *px, double *py);
void camera_invert(const struct camera *c, double px, double py, struct sampler *w);
/* Solid-angle density of camera_sample_dir (0 outside the film). */
double camera_pdf_dir(const struct camera *c, vec3 d);

#endif
