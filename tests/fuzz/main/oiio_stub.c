/* The fuzz build's stand-in for core/io/oiio_load.c: images are fuzz.h's raw texel files, so that
 * the scene target's textures reach the loader's texture code without OpenImageIO, whose
 * uninstrumented decoders are not what is fuzzed here. Writing is refused. */
#include "base/util.h"
#include "fuzz/fuzz.h"
#include "io/oiio.h"
#include <stdio.h>
#include <stdlib.h>

bool oiio_module_present(char *err, size_t errlen)
{
    snprintf(err, errlen, "the fuzz build has no OpenImageIO module");
    return false;
}

bool oiio_loaded(void) { return false; }

bool oiio_write(const char *path, int w, int h, int nchan, const float *px, char *err, size_t errlen)
{
    (void)w, (void)h, (void)nchan, (void)px;
    snprintf(err, errlen, "%s: the fuzz build writes no images", path);
    return false;
}

bool oiio_read_channels(const char *path, int *w, int *h, int *nchan, float **px, int *bits, char *err, size_t errlen)
{
    char *text = NULL;
    size_t n = 0;
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: cannot read image", path);
        return false;
    }
    FILE *m = open_memstream(&text, &n);
    int c;
    while ((c = fgetc(f)) != EOF)
        fputc(c, m);
    fclose(f);
    fclose(m);
    int b = 0;
    bool ok = raw_texels_parse((const uint8_t *)text, n, path, w, h, nchan, &b, px, err, errlen);
    free(text);
    if (bits) *bits = b;
    return ok;
}
