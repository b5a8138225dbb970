/* Per-pixel mixing counters and their image (see pixel_mixing.h). */
#include "stats/pixel_mixing.h"
#include "base/util.h"
#include <stdlib.h>

void pixmix_init(struct pixel_mixing *m, int w, int h)
{
    m->w = w;
    m->h = h;
    m->n = xcalloc(2 * (size_t)w * h, sizeof *m->n);
}

void pixmix_free(struct pixel_mixing *m)
{
    free(m->n);
    m->n = NULL;
}

void pixmix_merge(struct pixel_mixing *dst, const struct pixel_mixing *src)
{
    size_t n = 2 * (size_t)dst->w * dst->h;
    for (size_t i = 0; i < n; i++)
        dst->n[i] += src->n[i];
}

struct image *pixmix_image(const struct pixel_mixing *m)
{
    struct image *im = img_create(m->w, m->h);
    size_t cells = (size_t)m->w * m->h;
    for (size_t i = 0; i < cells; i++) {
        double r = m->n[2 * i] > 0 ? (double)m->n[2 * i + 1] / (double)m->n[2 * i] : 0;
        im->px[3 * i] = im->px[3 * i + 1] = im->px[3 * i + 2] = r;
    }
    return im;
}
