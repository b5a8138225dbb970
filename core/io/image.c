/* Framebuffers, splatting and atomic EXR/PNG output. */
#include "io/image.h"
#include "base/util.h"
#include "io/image_encode.h"
#include "io/oiio.h"
#include "io/texels.h"
#include <stdio.h>
#include <stdlib.h>

struct image *img_create(int w, int h)
{
    struct image *im = xmalloc(sizeof *im);
    im->w = w;
    im->h = h;
    im->px = xcalloc((size_t)w * h * 3, sizeof(double));
    im->tent = false;
    return im;
}

void img_destroy(struct image *im)
{
    if (!im) return;
    free(im->px);
    free(im);
}

void img_accumulate(struct image *dst, const struct image *src, double scale)
{
    ASSERT(dst->w == src->w && dst->h == src->h);
    size_t n = (size_t)dst->w * dst->h * 3;
    for (size_t i = 0; i < n; i++)
        dst->px[i] += scale * src->px[i];
}

rgb img_get(const struct image *im, int x, int y)
{
    const double *p = im->px + 3 * ((size_t)y * im->w + x);
    return v3(p[0], p[1], p[2]);
}

typedef bool (*encode_fn)(int w, int h, const float *px, unsigned char **bytes, size_t *len, char *err, size_t errlen);

struct write_job {
    int w, h;
    float *px;
    encode_fn encode;
};

static bool write_encoded(const char *tmp, void *ctx, char *err, size_t errlen)
{
    struct write_job *j = ctx;
    unsigned char *bytes = NULL;
    size_t len = 0;
    bool ok = j->encode(j->w, j->h, j->px, &bytes, &len, err, errlen) &&
              write_chunks(tmp, &(struct chunk){bytes, len}, 1, err, errlen);
    free(bytes);
    return ok;
}

static double srgb(double x)
{
    x = clampd(x, 0.0, 1.0);
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

static bool write_scaled(const struct image *im, double scale, bool tonemap, const char *path, char *err, size_t errlen)
{
    size_t n = (size_t)im->w * im->h * 3;
    struct write_job j = {im->w, im->h, xmalloc(n * sizeof(float)), tonemap ? png_encode_rgb8 : exr_encode_rgb};
    for (size_t i = 0; i < n; i++) {
        double v = im->px[i] * scale;
        j.px[i] = (float)(tonemap ? srgb(v) : v);
    }
    bool ok = atomic_write(path, write_encoded, &j, err, errlen);
    free(j.px);
    return ok;
}

bool img_write_exr(const struct image *im, double scale, const char *path, char *err, size_t errlen)
{
    return write_scaled(im, scale, false, path, err, errlen);
}

bool img_write_png(const struct image *im, double scale, const char *path, char *err, size_t errlen)
{
    return write_scaled(im, scale, true, path, err, errlen);
}

bool img_write_exr_png(const struct image *im, const char *prefix, char *err, size_t errlen)
{
    char path[4096];
    snprintf(path, sizeof path, "%s.exr", prefix);
    if (!img_write_exr(im, 1.0, path, err, errlen)) return false;
    snprintf(path, sizeof path, "%s.png", prefix);
    return img_write_png(im, 1.0, path, err, errlen);
}

bool img_read_rgb(const char *path, int *w, int *h, float **rgb, int *bits, char *err, size_t errlen)
{
    int nc;
    float *chan;
    if (!oiio_read_channels(path, w, h, &nc, &chan, bits, err, errlen)) return false;
    /* again here: the decoder is another module, and a stand-in for it in the fuzz build */
    bool ok = texels_check_size(path, *w, *h, nc, err, errlen);
    *rgb = ok ? texels_to_rgb(*w, *h, nc, chan) : NULL;
    free(chan);
    return ok;
}

struct image *img_read(const char *path, char *err, size_t errlen)
{
    int w, h;
    float *px;
    if (!img_read_rgb(path, &w, &h, &px, NULL, err, errlen)) return NULL;
    struct image *im = img_create(w, h);
    for (size_t i = 0; i < (size_t)w * h * 3; i++)
        im->px[i] = px[i];
    free(px);
    return im;
}

double img_mean_luminance(const struct image *im)
{
    double s = 0;
    for (int y = 0; y < im->h; y++)
        for (int x = 0; x < im->w; x++)
            s += luminance(img_get(im, x, y));
    return s / ((double)im->w * im->h);
}

double img_relmse(const struct image *a, const struct image *ref, double eps)
{
    ASSERT(a->w == ref->w && a->h == ref->h);
    size_t n = (size_t)a->w * a->h * 3;
    double s = 0;
    for (size_t i = 0; i < n; i++)
        s += sqr(a->px[i] - ref->px[i]) / (sqr(ref->px[i]) + eps);
    return s / n;
}
