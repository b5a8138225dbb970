/* Edge mask from primary hits at pixel centres (see edge_mask.h). */
#include "ch5/edge_mask.h"
#include "base/util.h"
#include "common/primary_hit.h"
#include <stdlib.h>

struct px_hit {
    bool hit, flat;
    int prim;
    double t;
    vec3 ng;
};

static bool boundary(const struct px_hit *a, const struct px_hit *b)
{
    if (a->hit != b->hit) return true;
    if (!a->hit) return false;
    if (a->prim != b->prim) return true;
    if (fabs(a->t - b->t) > 0.05 * fmin(a->t, b->t)) return true;
    return a->flat && vdot(a->ng, b->ng) < cos(2 * M_PI / 180);
}

bool *edge_mask(const struct scene *sc, int radius)
{
    int W = sc->cam.width, H = sc->cam.height;
    struct px_hit *px = xcalloc((size_t)W * H, sizeof *px);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            struct hit h;
            struct px_hit *p = &px[(size_t)y * W + x];
            p->hit = primary_hit(sc, x, y, &h);
            if (!p->hit) continue;
            const struct prim *pr = &sc->prims[h.prim];
            p->prim = h.prim;
            p->t = h.t;
            p->flat = pr->kind != PRIM_SPHERE && !pr->n;
            p->ng = pr->kind != PRIM_SPHERE ? pr->tri_n[h.tri] : v3s(0);
        }
    bool *edge = xcalloc((size_t)W * H, sizeof *edge), *mask = xcalloc((size_t)W * H, sizeof *mask);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            const struct px_hit *p = &px[(size_t)y * W + x];
            if ((x + 1 < W && boundary(p, p + 1)) || (y + 1 < H && boundary(p, p + W))) edge[(size_t)y * W + x] = true;
        }
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            for (int dy = -radius; dy <= radius && !mask[(size_t)y * W + x]; dy++)
                for (int dx = -radius; dx <= radius; dx++) {
                    int xx = x + dx, yy = y + dy;
                    if (xx >= 0 && yy >= 0 && xx < W && yy < H && edge[(size_t)yy * W + xx]) {
                        mask[(size_t)y * W + x] = true;
                        break;
                    }
                }
    free(px);
    free(edge);
    return mask;
}
