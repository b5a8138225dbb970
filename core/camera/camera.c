/* Pinhole and thin-lens camera, box or tent filter (camera.h). camera_setup() is the model's
 * (scene/camera_setup.c).
 *
 * Tungsten's PinholeCamera: the image plane at distance 1/tan(fov/2) spans x in [-1, 1] across the
 * width (fov is horizontal) and y in [-H/W, H/W]; raster x grows along +x and raster y grows
 * downward (local y = ratio - 2 py / W). At unit distance: for raster (px, py),
 *   x = tan_half_fov * (2 px / W - 1),  y = tan_half_fov * (1 - 2 py / H) / aspect,  z = 1,
 * in the basis (s = right, t = up, n = forward), also for film positions outside the image.
 * A = (2 tan_half_fov)^2 / aspect * (film area / image area) is the film's area at unit distance;
 * the solid-angle density of a uniform film position is 1 / (A cos^3 theta).
 *
 * Tungsten's ThinlensCamera: the lens point o = (ox, oy, 0) on a disc of radius aperture_size, the
 * ray toward f (x, y, 1), f = focus_distance. Divided by f the ray's direction is
 * (x - ox / f, y - oy / f, 1): the pinhole's with the film shifted by -o / f, so the film's area at
 * unit distance is still A and the density is again 1 / (A cos^3 theta) of the ray's own angle
 * (the focus-plane point has area density 1 / (A f^2), at distance f / cos theta from o). */
#include "camera/camera.h"
#include "sampling/warp.h"

static double plane_area(const struct camera *c)
{
    return 4 * c->tan_half_fov * c->tan_half_fov / c->aspect * camera_film_area(c) / ((double)c->width * c->height);
}

/* The lens point's offset from the lens centre over the focus distance, in (s, t). */
static void lens_shift(const struct camera *c, vec3 lens, double *sx, double *sy)
{
    vec3 o = vsub(lens, c->pos);
    *sx = vdot(o, c->basis.s) / c->focus_dist;
    *sy = vdot(o, c->basis.t) / c->focus_dist;
}

vec3 camera_sample_disc(const struct camera *c, struct sampler *s, double *pdf_area)
{
    double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS), x, y, r = c->lens_radius;
    warp_disk(u1, u2, &x, &y);
    *pdf_area = 1.0 / (M_PI * r * r);
    return vadd(c->pos, vadd(vscale(c->basis.s, r * x), vscale(c->basis.t, r * y)));
}

bool camera_invert_lens(const struct camera *c, vec3 p, struct sampler *w)
{
    if (!(c->lens_radius > 0)) return true;
    vec3 o = vsub(p, c->pos);
    double x = vdot(o, c->basis.s) / c->lens_radius, y = vdot(o, c->basis.t) / c->lens_radius, u1, u2;
    if (!(x * x + y * y <= 1 + 1e-9)) return false;
    warp_disk_invert(x, y, &u1, &u2);
    sampler_put(w, DIM_CONTINUOUS, u1 >= 1 ? nextafter(1.0, 0.0) : u1);
    sampler_put(w, DIM_CONTINUOUS, u2 >= 1 ? nextafter(1.0, 0.0) : u2);
    return true;
}

/* The world direction of the unit-distance local offset l = (x, y, 1) and its density. */
static inline vec3 dir_of(const struct camera *c, vec3 l, double *pdf)
{
    double len2 = vlen2(l), inv_len = 1.0 / sqrt(len2);
    if (pdf) *pdf = len2 * sqrt(len2) / plane_area(c); /* 1 / (A cos^3), cos = 1 / |l| */
    return vscale(frame_to_world(&c->basis, l), inv_len);
}

/* Image-normalised film position (box: the numbers themselves) of the raster position drawn. */
static inline void film_of(const struct camera *c, struct sampler *s, double *px, double *py, double *ix, double *iy)
{
    double ux = sampler_next(s, DIM_IMAGE_X), uy = sampler_next(s, DIM_IMAGE_Y);
    int m = camera_margin(c);
    *px = ux * camera_film_width(c) - m;
    *py = uy * camera_film_height(c) - m;
    *ix = m ? *px / c->width : ux;
    *iy = m ? *py / c->height : uy;
}

vec3 camera_sample_dir_pinhole(const struct camera *c, struct sampler *s, double *px, double *py, double *pdf)
{
    double ix, iy;
    film_of(c, s, px, py, &ix, &iy);
    return dir_of(c, v3(c->tan_half_fov * (2 * ix - 1), c->tan_half_fov * (1 - 2 * iy) / c->aspect, 1.0), pdf);
}

vec3 camera_sample_dir_lens(const struct camera *c, vec3 lens, struct sampler *s, double *px, double *py, double *pdf)
{
    double ix, iy, sx, sy;
    film_of(c, s, px, py, &ix, &iy);
    if (c->tungsten_defects) {
        ix = (*px - 0.5) / c->width;
        iy = (*py - 0.5) / c->height;
    }
    lens_shift(c, lens, &sx, &sy);
    return dir_of(c, v3(c->tan_half_fov * (2 * ix - 1) - sx, c->tan_half_fov * (1 - 2 * iy) / c->aspect - sy, 1.0),
                  pdf);
}

/* Raster position and density from the direction's offset (x, y) at unit distance through the
 * film's centre and its cosine; 0 off the film. */
static inline double raster_of(const struct camera *c, double x, double y, double ct, double *px, double *py)
{
    int m = camera_margin(c);
    double rx = 0.5 * (x / c->tan_half_fov + 1) * c->width,
           ry = 0.5 * (1 - y * c->aspect / c->tan_half_fov) * c->height;
    if (!(rx >= -m && rx < c->width + m && ry >= -m && ry < c->height + m)) return 0;
    *px = rx;
    *py = ry;
    return 1.0 / (plane_area(c) * ct * ct * ct);
}

double camera_raster_pinhole(const struct camera *c, vec3 d, double *px, double *py)
{
    vec3 l = frame_to_local(&c->basis, d);
    if (!(l.z > 0)) return 0;
    return raster_of(c, l.x / l.z, l.y / l.z, l.z / vlen(l), px, py);
}

/* The lens point's focus-plane point, over the focus distance, is the lens centre's offset plus
 * the lens shift (camera.c's header). */
double camera_raster_lens(const struct camera *c, vec3 lens, vec3 d, double *px, double *py)
{
    vec3 l = frame_to_local(&c->basis, d);
    if (!(l.z > 0)) return 0;
    double sx, sy;
    lens_shift(c, lens, &sx, &sy);
    return raster_of(c, l.x / l.z + sx, l.y / l.z + sy, l.z / vlen(l), px, py);
}

void camera_invert(const struct camera *c, double px, double py, struct sampler *w)
{
    int m = camera_margin(c);
    double ux = (px + m) / camera_film_width(c), uy = (py + m) / camera_film_height(c);
    sampler_put(w, DIM_IMAGE_X, ux < 0 ? 0 : ux >= 1 ? nextafter(1.0, 0.0) : ux);
    sampler_put(w, DIM_IMAGE_Y, uy < 0 ? 0 : uy >= 1 ? nextafter(1.0, 0.0) : uy);
}

double camera_tungsten_leak(const struct camera *c, vec3 lens, vec3 d, double *px, double *py)
{
    vec3 l = frame_to_local(&c->basis, d);
    if (!c->tungsten_defects || !(l.z > 0)) return 0;
    double sx, sy;
    lens_shift(c, lens, &sx, &sy);
    double x = 0.5 * ((l.x / l.z + sx) / c->tan_half_fov + 1) * c->width;
    double y = 0.5 * (1 - (l.y / l.z + sy) * c->aspect / c->tan_half_fov) * c->height;
    if (!(x >= -0.5 && x < c->width && y >= -0.5 && y < c->height) || (x >= 0 && y >= 0)) return 0;
    *px = x < 0 ? 0 : x;
    *py = y < 0 ? 0 : y;
    double ct = l.z / vlen(l);
    return 1.0 / (plane_area(c) * ct * ct * ct);
}
