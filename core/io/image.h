/* Framebuffers and image files. File I/O goes through core/io/oiio.cpp (OpenImageIO has no C API);
 * every write is atomic: a temporary file in the same directory, then rename(2). */
#ifndef IMAGE_H
#define IMAGE_H

#include "base/vecmath.h"
#include <stddef.h>

struct image {
    int w, h;
    double *px; /* 3 per pixel, row-major, row 0 on top */
    bool tent;  /* img_splat's reconstruction filter: tent of radius 1, else box */
};

struct image *img_create(int w, int h);
void img_destroy(struct image *im);
static inline void img_add(struct image *im, int x, int y, rgb c)
{
    double *p = im->px + 3 * ((size_t)y * im->w + x);
    p[0] += c.x;
    p[1] += c.y;
    p[2] += c.z;
}
/* A contribution at raster position (px, py). Box: all of it to the pixel containing the position.
 * Tent: to the 2x2 pixels whose centres lie within one pixel on each axis, weights
 * (1 - |dx|)(1 - |dy|), which sum to 1; the position may lie up to a pixel outside the image, and
 * pixels outside receive nothing (camera.h: the film is larger than the image by that margin). */
static inline void img_splat(struct image *im, double px, double py, rgb c)
{
    if (!im->tent) {
        if (!(px >= 0 && py >= 0)) return;
        int x = (int)px, y = (int)py;
        if (x >= im->w || y >= im->h) return;
        img_add(im, x, y, c);
        return;
    }
    if (!(px > -1 && px < im->w + 1 && py > -1 && py < im->h + 1)) return; /* no weight; also NaN */
    double fx = px - 0.5, fy = py - 0.5, x0 = floor(fx), y0 = floor(fy);
    double ax = fx - x0, ay = fy - y0, wx[2] = {1 - ax, ax}, wy[2] = {1 - ay, ay};
    for (int j = 0; j < 2; j++) {
        int y = (int)y0 + j;
        if (y < 0 || y >= im->h) continue;
        for (int i = 0; i < 2; i++) {
            int x = (int)x0 + i;
            if (x >= 0 && x < im->w) img_add(im, x, y, vscale(c, wx[i] * wy[j]));
        }
    }
}
void img_accumulate(struct image *dst, const struct image *src, double scale);
rgb img_get(const struct image *im, int x, int y);

/* Linear float EXR with the image scaled by `scale`. */
bool img_write_exr(const struct image *im, double scale, const char *path, char *err, size_t errlen);
/* Tone-mapped 8-bit PNG: exposure `scale`, clamp, sRGB transfer curve. */
bool img_write_png(const struct image *im, double scale, const char *path, char *err, size_t errlen);
/* PREFIX.exr (linear) and PREFIX.png (tone-mapped), both at scale 1. */
bool img_write_exr_png(const struct image *im, const char *prefix, char *err, size_t errlen);
/* Reads any OpenImageIO format as RGB float (grey is replicated, alpha dropped), values as stored:
 * no transfer curve is undone. *bits as in oiio_read_channels (NULL: not wanted). */
bool img_read_rgb(const char *path, int *w, int *h, float **rgb, int *bits, char *err, size_t errlen);
struct image *img_read(const char *path, char *err, size_t errlen);

/* Mean luminance over pixels (Rec. 709 weights, base/vecmath.h's luminance). */
double img_mean_luminance(const struct image *im);
/* Relative MSE against a reference: mean over pixels and channels of (a - r)^2 / (r^2 + eps). */
double img_relmse(const struct image *a, const struct image *ref, double eps);
#endif
