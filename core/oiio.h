/* The C face of core/oiio.cpp: the only code that talks to OpenImageIO. */
#ifndef OIIO_H
#define OIIO_H

#include <stdbool.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Writes nchan-channel float pixels (row 0 on top) to `path`; the format follows the extension,
 * 8-bit formats get values quantised from [0, 1]. Not atomic by itself. */
bool oiio_write(const char *path, int w, int h, int nchan, const float *px, char *err, size_t errlen);
/* Reads an image as 3-channel float; *px is malloc'ed. */
bool oiio_read_rgb(const char *path, int *w, int *h, float **px, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
