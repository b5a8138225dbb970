/* Bitmap textures as Tungsten's BitmapTexture reads them: loading through OpenImageIO, the 2.2 gamma
 * table for integer (LDR) files, bilinear lookup with wrap-around. */
#include "base/util.h"
#include "io/image.h"
#include "scene/scene.h"
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>

/* floor(255 (c/255)^2.2) / 255 for every 8-bit code c, built once; pow is exact enough that no
 * entry sits within rounding of an integer boundary (a test checks the entries against Tungsten's). */
static float gamma_table[256];
static pthread_once_t gamma_once = PTHREAD_ONCE_INIT;

static void gamma_build(void)
{
    for (int c = 0; c < 256; c++)
        gamma_table[c] = (float)(floor(255 * pow(c / 255.0, 2.2)) / 255);
}

float texture_gamma_decode(int code)
{
    pthread_once(&gamma_once, gamma_build);
    return gamma_table[code < 0 ? 0 : code > 255 ? 255 : code];
}

/* The 8-bit code of a value read from a `bits`-bit integer file: the code itself for 8 bits, the
 * high byte for wider formats (what lodepng hands Tungsten for a 16-bit PNG). */
static int code8(float f, int bits)
{
    double c = (double)f * (ldexp(1.0, bits) - 1); /* the file's integer code */
    double r = floor(c + 0.5);
    if (!(r > 0)) return 0;
    double code = bits > 8 ? floor(ldexp(r, 8 - bits)) : r; /* high byte: the shift, truncated */
    /* clamped as a double: a texel far above 1 would overflow the conversion to int */
    return code > 255 ? 255 : (int)code;
}

struct texture *texture_load(const char *path, char *err, size_t errlen)
{
    int w, h, bits = 0;
    float *px;
    if (!img_read_rgb(path, &w, &h, &px, &bits, err, errlen)) return NULL;
    return texture_from_rgb(path, w, h, px, bits, err, errlen);
}

/* nested BSDFs (mixed's ratio): Tungsten's scalar bitmap for REQUEST_AVERAGE. An integer file's
 * texel is the integer mean of its three 8-bit codes over 255, WITHOUT the gamma table (ImageIO's
 * loadLdr applies it to RGB requests only); a float file's is the mean of its channels. The scalar is
 * stored in all three channels, so texture_lookup returns it in each. */
struct texture *texture_load_average(const char *path, char *err, size_t errlen)
{
    int w, h, bits = 0;
    float *px;
    if (!img_read_rgb(path, &w, &h, &px, &bits, err, errlen)) return NULL;
    for (size_t i = 0; i < (size_t)w * h; i++) {
        float *t = px + 3 * i, v;
        if (!isfinite(t[0]) || !isfinite(t[1]) || !isfinite(t[2])) {
            snprintf(err, errlen, "%s: non-finite texel value", path);
            free(px);
            return NULL;
        }
        if (bits > 0 && bits <= 32)
            v = (float)((code8(t[0], bits) + code8(t[1], bits) + code8(t[2], bits)) / 3) / 255;
        else
            v = (t[0] + t[1] + t[2]) / 3;
        t[0] = t[1] = t[2] = v;
    }
    struct texture *t = xmalloc(sizeof *t);
    t->w = w;
    t->h = h;
    t->bits = bits;
    t->rgb = px;
    return t;
}

struct texture *texture_from_rgb(const char *path, int w, int h, float *px, int bits, char *err, size_t errlen)
{
    size_t n = (size_t)w * h * 3;
    for (size_t i = 0; i < n; i++)
        if (!isfinite(px[i])) {
            snprintf(err, errlen, "%s: non-finite texel value", path);
            free(px);
            return NULL;
        }
    if (bits > 0 && bits <= 32)
        for (size_t i = 0; i < n; i++)
            px[i] = texture_gamma_decode(code8(px[i], bits));
    struct texture *t = xmalloc(sizeof *t);
    t->w = w;
    t->h = h;
    t->bits = bits;
    t->rgb = px;
    return t;
}

/* floor without the libm call that baseline x86-64 makes of it (no SSE4.1 round instruction);
 * NaN, infinities and huge values take the library's. */
static inline double floor_fast(double x)
{
    if (!(fabs(x) < 0x1p62)) return floor(x);
    double f = (double)(long long)x;
    return f > x ? f - 1 : f;
}

/* s in [0, 1) across n texels -> the two texels whose centres (at +0.5) bracket it, wrapped
 * around, and the weight of the second. */
static inline int bracket(double s, int n, int *i1, double *f)
{
    double x = s * n - 0.5; /* >= -0.5, so truncating x + 1 floors it */
    int i0 = (int)(x + 1) - 1;
    *f = x - i0;
    if (i0 < 0) i0 = n - 1;
    *i1 = i0 + 1 >= n ? 0 : i0 + 1;
    return i0 >= n ? n - 1 : i0;
}

rgb texture_lookup(const struct texture *t, double u, double v)
{
    /* One period first (texel coordinates then stay small whatever u and v are); r runs down from
     * the top row. */
    double s = u - floor_fast(u), r = (1 - v) - floor_fast(1 - v);
    if (!(s >= 0 && s < 1)) s = 0; /* NaN, infinities, and s rounded up to 1 */
    if (!(r >= 0 && r < 1)) r = 0;
    int x1, y1;
    double fx, fy;
    int x0 = bracket(s, t->w, &x1, &fx);
    int y0 = bracket(r, t->h, &y1, &fy);
    const float *p00 = t->rgb + 3 * ((size_t)y0 * t->w + x0), *p01 = t->rgb + 3 * ((size_t)y0 * t->w + x1);
    const float *p10 = t->rgb + 3 * ((size_t)y1 * t->w + x0), *p11 = t->rgb + 3 * ((size_t)y1 * t->w + x1);
    double w00 = (1 - fx) * (1 - fy), w01 = fx * (1 - fy), w10 = (1 - fx) * fy, w11 = fx * fy;
    return v3(w00 * p00[0] + w01 * p01[0] + w10 * p10[0] + w11 * p11[0],
              w00 * p00[1] + w01 * p01[1] + w10 * p10[1] + w11 * p11[1],
              w00 * p00[2] + w01 * p01[2] + w10 * p10[2] + w11 * p11[2]);
}

void texture_free(struct texture *t)
{
    if (!t) return;
    free(t->rgb);
    free(t);
}
