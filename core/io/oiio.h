/* The C face of core/io/oiio.cpp: the only code that talks to OpenImageIO.
 *
 * oiio_write and oiio_read_channels (core/io/oiio_load.c) open the module oiio.so, which holds
 * oiio.cpp, on first use and forward to its oiio_module_* functions. The module is looked for in
 * the directory of the running executable, where the build puts a copy; if it cannot be opened the
 * call fails with an error naming the file. The harness's own EXR and PNG outputs do not come here
 * (io/image_encode.h); oiio_write serves the tests, which make textures in other formats. */
#ifndef OIIO_H
#define OIIO_H

#include <stdbool.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Writes nchan-channel float pixels (row 0 on top) to `path`; the format follows the extension,
 * 8-bit formats get values quantised from [0, 1]. Not atomic by itself; on failure err holds the
 * reason only (atomic_write names the file). */
bool oiio_write(const char *path, int w, int h, int nchan, const float *px, char *err, size_t errlen);
/* Reads an image's every channel as float (an integer format's codes divided by their maximum, no
 * colour conversion, alpha not multiplied in), refusing sizes beyond io/texels.h's limits from the
 * header, before the texels are allocated; *px (w*h*nchan) is malloc'ed. *bits (if not NULL) gets the
 * file's bits per channel when its format is an integer one (8 for most PNG/JPEG, 16 for 16-bit
 * PNG/TIFF), else 0 (half or float: EXR, HDR, PFM, float TIFF). */
bool oiio_read_channels(const char *path, int *w, int *h, int *nchan, float **px, int *bits, char *err, size_t errlen);
/* Whether the module file is there, without opening it: tools that will write images check this
 * before a long run rather than fail at its end. */
bool oiio_module_present(char *err, size_t errlen);
/* True once the module has been opened in this process (tests check that it is not, before any
 * image is touched). */
bool oiio_loaded(void);

/* The module's entry points. Encoding fills a malloc'ed buffer with the file's bytes (format from
 * the extension of `path`, which is not touched); oiio_write writes it out. */
bool oiio_module_encode(const char *path, int w, int h, int nchan, const float *px, unsigned char **bytes, size_t *len,
                        char *err, size_t errlen);
bool oiio_module_read_channels(const char *path, int *w, int *h, int *nchan, float **px, int *bits, char *err,
                               size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
