/* Pinhole or thin-lens camera with a box or tent reconstruction filter.
 * Raster coordinates: x to the right, y downward (row 0 on top), pixel (i, j) = [i, i+1) x [j, j+1).
 * The film is the image grown by the filter's margin m on every side (0 for box; 1 for the tent,
 * whose support reaches one pixel beyond a border pixel's centre): x in [-m, width + m),
 * y in [-m, height + m). The image dims map linearly onto it, x = -m + u_x * film_width.
 *
 * The camera vertex ("lens point") is pos for the pinhole and a uniform point of the aperture disc
 * (radius lens_radius about pos, in the image plane's (s, t) directions) for the thin lens. A ray
 * leaves the lens point toward the point of the plane in focus (distance focus_dist along n) that
 * the lens centre sees at the raster position, so every lens point maps the film onto the same
 * focus-plane points; the pinhole is the thin lens of radius 0.
 *
 * Importance is normalised over the film and the aperture, per unit lens area and unit solid angle
 * with no cosine at the lens (edges into the camera vertex carry cosine 1, path.h):
 * We(p, d) = p_lens(p) camera_pdf_dir(p, d), p_lens = 1 / (pi r^2) (a Dirac point for the pinhole).
 * Sampling the lens point then the direction has exactly this density, so the camera vertex's
 * throughput is 1 and a connection to it (t = 1) carries We / p_lens = camera_pdf_dir(p, d). An
 * image estimate is (film area / N) * sum of filter-weighted splats (image.h) over N camera
 * samples, for every technique. Tungsten's camera does the same for the tent: a pixel, then an
 * offset drawn from the tent, so that both measure pixel j as the tent-weighted integral of
 * radiance around its centre.
 *
 * Numbers of the camera vertex's block (STREAM_CAMERA, vertex 0): the lens point first (2
 * DIM_CONTINUOUS, thin lens only), then DIM_IMAGE_X, DIM_IMAGE_Y. A lone camera vertex (light
 * tracing's t = 1) reads only the lens numbers, which stay the same when its subpath grows. */
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
/* Numbers camera_sample_lens reads at the start of block 0. */
static inline int camera_lens_dims(const struct camera *c) { return c->lens_radius > 0 ? 2 : 0; }

/* The thin lens's point: a uniform point of the aperture disc and its area density 1/(pi r^2). */
vec3 camera_sample_disc(const struct camera *c, struct sampler *s, double *pdf_area);
/* The camera vertex: a uniform lens point and its area density (pos and 1 for the pinhole, which
 * reads no number; inline, so the pinhole pays no call). */
static inline vec3 camera_sample_lens(const struct camera *c, struct sampler *s, double *pdf_area)
{
    if (!(c->lens_radius > 0)) {
        *pdf_area = 1;
        return c->pos;
    }
    return camera_sample_disc(c, s, pdf_area);
}
/* Puts the numbers that make camera_sample_lens return p (none for the pinhole); false when p is
 * not on the aperture. */
bool camera_invert_lens(const struct camera *c, vec3 p, struct sampler *w);
/* Consumes DIM_IMAGE_X then DIM_IMAGE_Y; returns the unit world direction of the primary ray from
 * lens point `lens` and, if pdf is not NULL, its camera_pdf_dir (known here without a projection). */
vec3 camera_sample_dir_pinhole(const struct camera *c, struct sampler *s, double *px, double *py, double *pdf);
vec3 camera_sample_dir_lens(const struct camera *c, vec3 lens, struct sampler *s, double *px, double *py, double *pdf);
/* Raster position seen along world direction d from lens point `lens`, and camera_pdf_dir(lens, d)
 * (returned: 0 if behind or outside the film, then px, py are not set). */
double camera_raster_pinhole(const struct camera *c, vec3 d, double *px, double *py);
double camera_raster_lens(const struct camera *c, vec3 lens, vec3 d, double *px, double *py);
/* The entry points: inline, so that the pinhole neither copies the lens point (24 bytes, passed
 * in memory) nor pays for the lens (BDPT on scenes/cornell-box: +0.5 % instructions otherwise). */
static inline vec3 camera_sample_dir(const struct camera *c, vec3 lens, struct sampler *s, double *px, double *py,
                                     double *pdf)
{
    return c->lens_radius > 0 ? camera_sample_dir_lens(c, lens, s, px, py, pdf)
                              : camera_sample_dir_pinhole(c, s, px, py, pdf);
}
static inline double camera_raster(const struct camera *c, vec3 lens, vec3 d, double *px, double *py)
{
    return c->lens_radius > 0 ? camera_raster_lens(c, lens, d, px, py) : camera_raster_pinhole(c, d, px, py);
}
/* Solid-angle density of camera_sample_dir from lens point `lens` (0 outside the film). */
static inline double camera_pdf_dir(const struct camera *c, vec3 lens, vec3 d)
{
    double px, py;
    return camera_raster(c, lens, d, &px, &py);
}
/* Puts the image numbers of raster position (px, py) (after camera_invert_lens for a thin lens). */
void camera_invert(const struct camera *c, double px, double py, struct sampler *w);

/* With c->tungsten_defects (tests only, scene.h): the importance camera_raster would give for a
 * direction whose film position lies in Tungsten's leak strip [-1/2, 0) of either axis, with the
 * raster moved onto pixel 0; else 0. */
double camera_tungsten_leak(const struct camera *c, vec3 lens, vec3 d, double *px, double *py);

#endif
