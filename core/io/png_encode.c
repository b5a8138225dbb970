/* 8-bit PNG encoding through libpng's simplified API into memory (see image_encode.h for why). */
#include "base/util.h"
#include "io/image_encode.h"
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bool png_encode_rgb8(int w, int h, const float *px, unsigned char **bytes, size_t *len, char *err, size_t errlen)
{
    size_t n = (size_t)w * h * 3;
    unsigned char *codes = xmalloc(n);
    for (size_t i = 0; i < n; i++) {
        float v = px[i] != px[i] ? 0.0f : px[i] < 0 ? 0.0f : px[i] > 1 ? 1.0f : px[i];
        codes[i] = (unsigned char)roundf(v * 255.0f); /* OpenImageIO's rounding: a float product, halves up */
    }
    png_image im;
    memset(&im, 0, sizeof im);
    im.version = PNG_IMAGE_VERSION;
    im.width = (png_uint_32)w;
    im.height = (png_uint_32)h;
    im.format = PNG_FORMAT_RGB;
    png_alloc_size_t size = 0;
    /* first the size, then the bytes */
    bool ok = png_image_write_to_memory(&im, NULL, &size, 0, codes, 0, NULL);
    unsigned char *out = ok ? xmalloc(size) : NULL;
    ok = ok && png_image_write_to_memory(&im, out, &size, 0, codes, 0, NULL);
    if (!ok) {
        snprintf(err, errlen, "libpng: %s", im.message[0] ? im.message : "cannot encode");
        free(out);
        out = NULL;
    }
    png_image_free(&im);
    free(codes);
    *bytes = out;
    *len = ok ? (size_t)size : 0;
    return ok;
}
