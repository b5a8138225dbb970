/* Pinhole camera, box filter (camera.h). camera_setup() lives with the loader.
 *
 * Tungsten's PinholeCamera: the image plane at distance 1/tan(fov/2) spans x in [-1, 1] across the
 * width (fov is horizontal) and y in [-H/W, H/W]; raster x grows along +x and raster y grows
 * downward (local y = ratio - 2 py / W). At unit distance: for raster (px, py),
 *   x = tan_half_fov * (2 px / W - 1),  y = tan_half_fov * (1 - 2 py / H) / aspect,  z = 1,
 * in the basis (s = right, t = up, n = forward). A = (2 tan_half_fov)^2 / aspect is the image area
 * at unit distance; the solid-angle density of a uniform raster position is 1 / (A cos^3 theta). */
#include "camera.h"

static double plane_area(const struct camera *c) { return 4 * c->tan_half_fov * c->tan_half_fov / c->aspect; }

vec3 camera_sample_dir(const struct camera *c, struct sampler *s, double *px, double *py, double *pdf)
{
    double ux = sampler_next(s, DIM_IMAGE_X), uy = sampler_next(s, DIM_IMAGE_Y);
    *px = ux * c->width;
    *py = uy * c->height;
    vec3 l = v3(c->tan_half_fov * (2 * ux - 1), c->tan_half_fov * (1 - 2 * uy) / c->aspect, 1.0);
    double len2 = vlen2(l), inv_len = 1.0 / sqrt(len2);
    if (pdf) *pdf = len2 * sqrt(len2) / plane_area(c); /* 1 / (A cos^3), cos = 1 / |l| */
    return vscale(frame_to_world(&c->basis, l), inv_len);
}

/* Unit-square image coordinates of world direction d; false if behind the camera. */
static bool image_uv(const struct camera *c, vec3 d, double *ux, double *uy, double *cos_theta)
{
    vec3 l = frame_to_local(&c->basis, d);
    if (!(l.z > 0)) return false;
    double x = l.x / l.z, y = l.y / l.z;
    *ux = 0.5 * (x / c->tan_half_fov + 1);
    *uy = 0.5 * (1 - y * c->aspect / c->tan_half_fov);
    *cos_theta = l.z / vlen(l);
    return true;
}

double camera_raster(const struct camera *c, vec3 d, double *px, double *py)
{
    double ux, uy, ct;
    if (!image_uv(c, d, &ux, &uy, &ct)) return 0;
    if (!(ux >= 0 && ux < 1 && uy >= 0 && uy < 1)) return 0;
    *px = ux * c->width;
    *py = uy * c->height;
    return 1.0 / (plane_area(c) * ct * ct * ct);
}

void camera_invert(const struct camera *c, double px, double py, struct sampler *w)
{
    double ux = px / c->width, uy = py / c->height;
    sampler_put(w, DIM_IMAGE_X, ux < 0 ? 0 : ux >= 1 ? nextafter(1.0, 0.0) : ux);
    sampler_put(w, DIM_IMAGE_Y, uy < 0 ? 0 : uy >= 1 ? nextafter(1.0, 0.0) : uy);
}

double camera_pdf_dir(const struct camera *c, vec3 d)
{
    double px, py;
    return camera_raster(c, d, &px, &py);
}
