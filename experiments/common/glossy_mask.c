/* Glossy first hits per pixel (glossy_mask.h). */
#include "common/glossy_mask.h"
#include "base/util.h"
#include "common/primary_hit.h"

bool bsdf_is_glossy(const struct bsdf *b)
{
    switch (b->type) {
    case BSDF_ROUGH_CONDUCTOR:
    case BSDF_ROUGH_DIELECTRIC:
    case BSDF_ROUGH_PLASTIC:
    case BSDF_ROUGH_COAT:
    case BSDF_PHONG:
        return true;
    case BSDF_TRANSPARENCY:
    case BSDF_SMOOTH_COAT:
        return bsdf_is_glossy(b->child[0]);
    case BSDF_MIXED:
        return bsdf_is_glossy(b->child[0]) || bsdf_is_glossy(b->child[1]);
    default:
        return false;
    }
}

bool *glossy_mask(const struct scene *sc, int *count)
{
    int W = sc->cam.width, H = sc->cam.height;
    bool *mask = xcalloc((size_t)W * H, sizeof *mask);
    *count = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            struct hit h;
            if (!primary_hit(sc, x, y, &h)) continue;
            int b = sc->prims[h.prim].bsdf;
            mask[(size_t)y * W + x] = b >= 0 && bsdf_is_glossy(&sc->bsdfs[b]);
            *count += mask[(size_t)y * W + x];
        }
    return mask;
}
