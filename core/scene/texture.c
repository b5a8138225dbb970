/* Textures as Tungsten reads them: bitmaps as its BitmapTexture (loading through OpenImageIO, the
 * 2.2 gamma table for integer (LDR) files, bilinear lookup with wrap-around, the slope a bump map
 * reads), checkerboards as its CheckerTexture, constants. */
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

/* Texels -> texture: refuses non-finite values; `average` = Tungsten's REQUEST_AVERAGE, else RGB
 * with an integer file's codes gamma-decoded. */
static struct texture *from_texels(const char *path, int w, int h, float *px, int bits, bool average, char *err,
                                   size_t errlen)
{
    size_t n = (size_t)w * h * 3;
    for (size_t i = 0; i < n; i++)
        if (!isfinite(px[i])) {
            snprintf(err, errlen, "%s: non-finite texel value", path);
            free(px);
            return NULL;
        }
    bool ldr = bits > 0 && bits <= 32;
    if (average) {
        /* Tungsten's loadLdr averages the raw 8-bit codes in integers, truncating, and does not
         * gamma-decode them (its table is for RGB requests only); float files average as floats. */
        for (size_t i = 0; i < n; i += 3) {
            double m = ldr ? ((code8(px[i], bits) + code8(px[i + 1], bits) + code8(px[i + 2], bits)) / 3) / 255.0
                           : ((double)px[i] + px[i + 1] + px[i + 2]) / 3;
            px[i] = px[i + 1] = px[i + 2] = (float)m;
        }
    } else if (ldr) {
        for (size_t i = 0; i < n; i++)
            px[i] = texture_gamma_decode(code8(px[i], bits));
    }
    struct texture *t = xcalloc(1, sizeof *t);
    t->kind = TEX_BITMAP;
    t->w = w;
    t->h = h;
    t->bits = bits;
    t->rgb = px;
    return t;
}

static struct texture *load(const char *path, bool average, char *err, size_t errlen)
{
    int w, h, bits = 0;
    float *px;
    if (!img_read_rgb(path, &w, &h, &px, &bits, err, errlen)) return NULL;
    return from_texels(path, w, h, px, bits, average, err, errlen);
}

struct texture *texture_load(const char *path, char *err, size_t errlen) { return load(path, false, err, errlen); }

struct texture *texture_load_average(const char *path, char *err, size_t errlen)
{
    return load(path, true, err, errlen);
}

struct texture *texture_from_rgb(const char *path, int w, int h, float *px, int bits, char *err, size_t errlen)
{
    return from_texels(path, w, h, px, bits, false, err, errlen);
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

static rgb bitmap_lookup(const struct texture *t, double u, double v)
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

/* Tungsten converts u res to an int, which truncates toward zero (so the cells either side of
 * u = 0 share an index); parity of negative indices as two's complement. Values no int holds
 * (and NaN) take cell 0. */
static inline long long cell(double x) { return fabs(x) < 0x1p62 ? (long long)x : 0; }

rgb texture_lookup(const struct texture *t, double u, double v)
{
    if (t->kind == TEX_BITMAP) return bitmap_lookup(t, u, v);
    if (t->kind == TEX_CONSTANT) return t->on;
    return ((cell(u * t->res_u) ^ cell(v * t->res_v)) & 1) ? t->on : t->off;
}

/* Mean of the channels of texel (x, y), both in range. */
static inline double texel_mean(const struct texture *t, int x, int y)
{
    const float *p = t->rgb + 3 * ((size_t)y * t->w + x);
    return ((double)p[0] + p[1] + p[2]) / 3;
}

void texture_derivs(const struct texture *t, double u, double v, double d[2])
{
    d[0] = d[1] = 0;
    if (t->kind != TEX_BITMAP) return;
    /* Texel coordinates with centres on integers, split as Tungsten splits them: the integer part
     * truncated toward zero (not floored), so just left of u = 0 the fraction is negative and the
     * blend extrapolates, as Tungsten's does. */
    double x = u * t->w - 0.5, y = (1 - v) * t->h - 0.5;
    if (!(fabs(x) < 0x1p30 && fabs(y) < 0x1p30)) return;
    int ix = (int)x, iy = (int)y;
    double fx = x - ix, fy = y - iy;
    ix = ((ix % t->w) + t->w) % t->w;
    iy = ((iy % t->h) + t->h) % t->h;
    /* Columns x0..x3 and rows y0..y3 around the cell (x1, y1)-(x2, y2), wrapped. */
    int xs[4] = {ix == 0 ? t->w - 1 : ix - 1, ix, (ix + 1) % t->w, (ix + 2) % t->w};
    int ys[4] = {iy == 0 ? t->h - 1 : iy - 1, iy, (iy + 1) % t->h, (iy + 2) % t->h};
    /* Central differences at the four corners of the cell, (row, column) = (1, 1), (1, 2), (2, 1),
     * (2, 2): along the row for d[0], along the column for d[1]. */
    double du[2][2], dv[2][2];
    for (int r = 0; r < 2; r++)
        for (int c = 0; c < 2; c++) {
            du[r][c] = texel_mean(t, xs[c + 2], ys[r + 1]) - texel_mean(t, xs[c], ys[r + 1]);
            dv[r][c] = texel_mean(t, xs[c + 1], ys[r + 2]) - texel_mean(t, xs[c + 1], ys[r]);
        }
    d[0] = (du[0][0] * (1 - fx) + du[0][1] * fx) * (1 - fy) + (du[1][0] * (1 - fx) + du[1][1] * fx) * fy;
    d[1] = (dv[0][0] * (1 - fx) + dv[0][1] * fx) * (1 - fy) + (dv[1][0] * (1 - fx) + dv[1][1] * fx) * fy;
}

struct texture *texture_checker(rgb on, rgb off, int res_u, int res_v)
{
    struct texture *t = xcalloc(1, sizeof *t);
    t->kind = TEX_CHECKER;
    t->on = on;
    t->off = off;
    t->res_u = res_u;
    t->res_v = res_v;
    return t;
}

struct texture *texture_constant(rgb value)
{
    struct texture *t = xcalloc(1, sizeof *t);
    t->kind = TEX_CONSTANT;
    t->on = t->off = value;
    return t;
}

void texture_free(struct texture *t)
{
    if (!t) return;
    free(t->rgb);
    free(t);
}
