/* From an image file's decoded channels to the 3-channel texels the renderer keeps: the size and
 * channel checks (base/input_limits.h) made on the file's header before any texel is allocated, and
 * the channel mapping. OpenImageIO's module (oiio.cpp) checks the header with texels_check_size; the
 * rest runs in the core, where the fuzz target tests/fuzz/fuzz_texture.c reaches it without a
 * decoder. */
#ifndef TEXELS_H
#define TEXELS_H

#include "base/input_limits.h"
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* Inline so that the module, which links nothing of the core, shares the very same test. */
static inline bool texels_check_size(const char *path, long w, long h, long nc, char *err, size_t errlen)
{
    if (w <= 0 || h <= 0 || nc <= 0) {
        snprintf(err, errlen, "%s: empty image (%ldx%ld, %ld channels)", path, w, h, nc);
        return false;
    }
    if (w > LIMIT_TEXTURE_SIDE || h > LIMIT_TEXTURE_SIDE || w * h > LIMIT_TEXTURE_TEXELS) {
        snprintf(err, errlen, "%s: %ldx%ld texels, above the limit of %ld (16384x8192) in all and %d per side", path, w,
                 h, LIMIT_TEXTURE_TEXELS, LIMIT_TEXTURE_SIDE);
        return false;
    }
    if (nc > LIMIT_TEXTURE_CHANNELS || w * h * nc > LIMIT_TEXTURE_VALUES) {
        snprintf(err, errlen, "%s: %ld channels of %ldx%ld texels, above the limit of %d channels and %ld values", path,
                 nc, w, h, LIMIT_TEXTURE_CHANNELS, LIMIT_TEXTURE_VALUES);
        return false;
    }
    return true;
}

/* w*h texels of nc channels each (row 0 on top) → 3 channels, malloc'ed: the first three, or the
 * first one three times for a grey (or grey and alpha) file. The size must have passed
 * texels_check_size. */
float *texels_to_rgb(int w, int h, int nc, const float *chan);

#endif
