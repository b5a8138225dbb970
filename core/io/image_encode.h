/* The two formats every run writes, encoded into memory by their reference libraries: EXR through
 * OpenEXR's C core (core/io/exr_encode.c), PNG through libpng (core/io/png_encode.c). Both are
 * linked in; OpenImageIO's module (io/oiio.h) stays for reading, whose formats are open-ended.
 * Why not OpenImageIO here too: opening its module maps about 260 libraries, 0.2-0.4 s that every
 * process writing an image paid at its end, more than a short render's whole rendering
 * (core/io/NOTES.md). The caller writes the bytes (write_chunks: every write checked). */
#ifndef IMAGE_ENCODE_H
#define IMAGE_ENCODE_H

#include <stdbool.h>
#include <stddef.h>

/* w*h RGB float pixels, row 0 on top, as a scanline EXR of three FLOAT channels (R, G, B) with ZIP
 * compression, the layout OpenImageIO wrote; *bytes is malloc'ed. On failure err holds the reason. */
bool exr_encode_rgb(int w, int h, const float *px, unsigned char **bytes, size_t *len, char *err, size_t errlen);
/* w*h RGB pixels in [0, 1] (clamped), row 0 on top, as an 8-bit RGB PNG: each value v becomes the
 * code round(255 v) of the float product, halves up: OpenImageIO's rounding, so the files hold
 * the codes its writer gave. */
bool png_encode_rgb8(int w, int h, const float *px, unsigned char **bytes, size_t *len, char *err, size_t errlen);

#endif
