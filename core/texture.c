/* Bitmap textures: loading through OpenImageIO and nearest-texel lookup. */
#include "image.h"
#include "scene.h"
#include "util.h"
#include <stdio.h>
#include <stdlib.h>

struct texture *texture_load(const char *path, char *err, size_t errlen)
{
    int w, h;
    float *px;
    if (!img_read_rgb(path, &w, &h, &px, err, errlen)) return NULL;
    size_t n = (size_t)w * h * 3;
    for (size_t i = 0; i < n; i++)
        if (!isfinite(px[i])) {
            snprintf(err, errlen, "%s: non-finite texel value", path);
            free(px);
            return NULL;
        }
    struct texture *t = xmalloc(sizeof *t);
    t->w = w;
    t->h = h;
    t->rgb = px;
    return t;
}

static int wrap(double x, int n)
{
    /* floor before the modulo keeps negative coordinates periodic instead of mirrored. */
    if (!isfinite(x)) return 0;
    double f = floor(x * n);
    double m = fmod(f, (double)n);
    if (m < 0) m += n;
    int i = (int)m;
    return i >= n ? n - 1 : i;
}

rgb texture_lookup(const struct texture *t, double u, double v)
{
    int x = wrap(u, t->w);
    int y = t->h - 1 - wrap(v, t->h); /* v = 0 is the bottom row; row 0 of the bitmap is the top */
    const float *p = t->rgb + 3 * ((size_t)y * t->w + x);
    return v3(p[0], p[1], p[2]);
}

void texture_free(struct texture *t)
{
    if (!t) return;
    free(t->rgb);
    free(t);
}
