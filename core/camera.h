/* Pinhole camera with a box reconstruction filter.
 * Raster coordinates: x in [0, width) to the right, y in [0, height) downward (row 0 on top).
 * The image dims map as x = u_x * width, y = u_y * height.
 * Importance is normalised so that We(d) = camera_pdf_dir(d): an image estimate is
 * (width * height / N) * sum of splatted contributions over N camera samples, for every technique. */
#ifndef CAMERA_H
#define CAMERA_H

#include "sampler.h"
#include "scene.h"

/* Consumes DIM_IMAGE_X then DIM_IMAGE_Y; returns the unit world direction of the primary ray and,
 * if pdf is not NULL, its camera_pdf_dir (known here without a second projection). */
vec3 camera_sample_dir(const struct camera *c, struct sampler *s, double *px, double *py, double *pdf);
/* Raster position seen along world direction d from the camera, and camera_pdf_dir(d) (returned:
 * 0 if behind or outside the image, then px, py are not set). */
double camera_raster(const struct camera *c, vec3 d, double *px, double *py);
void camera_invert(const struct camera *c, double px, double py, struct sampler *w);
/* Solid-angle density of camera_sample_dir (0 outside the image). */
double camera_pdf_dir(const struct camera *c, vec3 d);

/* Builds the basis from position, look_at and up as Tungsten does; computes derived fields. */
void camera_setup(struct camera *c, vec3 pos, vec3 look_at, vec3 up, double fov_deg, int w, int h);

/* Changes the resolution keeping position, basis and horizontal fov. */
void camera_resize(struct camera *c, int w, int h);

#endif
