/* nftw */
#define _XOPEN_SOURCE 700
/* The fuzz targets' shared pieces (fuzz.h): a private directory, file slots, the message check, the
 * raw texel format. */
#include "base/util.h"
#include "fuzz/fuzz.h"
#include "io/texels.h"
#include <ftw.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[64];
static pthread_once_t dir_once = PTHREAD_ONCE_INIT;

static int rm_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
    (void)st, (void)flag, (void)ftw;
    return remove(path);
}

static void dir_remove(void)
{
    if (dir[0]) nftw(dir, rm_entry, 8, FTW_DEPTH | FTW_PHYS);
}

static void dir_make(void)
{
    const char *tmp = getenv("TMPDIR");
    snprintf(dir, sizeof dir, "%.40s/pss-fuzz-XXXXXX", tmp && tmp[0] && strlen(tmp) < 40 ? tmp : "/tmp");
    if (!mkdtemp(dir)) {
        perror("fuzz: mkdtemp");
        abort();
    }
    atexit(dir_remove);
}

const char *fuzz_dir(void)
{
    pthread_once(&dir_once, dir_make);
    return dir;
}

const char *fuzz_write(const char *name, const void *data, size_t n, char *path, size_t pathlen)
{
    snprintf(path, pathlen, "%s/%s", fuzz_dir(), name);
    FILE *f = fopen(path, "wb");
    if (!f || (n && fwrite(data, 1, n, f) != n) || fclose(f) != 0) {
        perror(path);
        abort();
    }
    return path;
}

void fuzz_check_message(const char *err)
{
    bool bad = !err[0];
    for (const char *p = err; *p; p++)
        if ((unsigned char)*p < 32 || *p == 127) bad = true;
    if (bad) {
        fprintf(stderr, "fuzz: the reader's message is not one printable line: \"");
        for (const char *p = err; *p; p++)
            fprintf(stderr, (unsigned char)*p < 32 ? "\\x%02x" : "%c", *p);
        fprintf(stderr, "\"\n");
        abort();
    }
}

int raw_texels_parse(const uint8_t *d, size_t size, const char *name, int *w, int *h, int *nc, int *bits, float **px,
                     char *err, size_t errlen)
{
    *px = NULL;
    if (size < 6) {
        snprintf(err, errlen, "%s: truncated header", name);
        return 0;
    }
    *w = d[0] | d[1] << 8;
    *h = d[2] | d[3] << 8;
    *nc = d[4];
    *bits = d[5];
    if (!texels_check_size(name, *w, *h, *nc, err, errlen)) return 0;
    size_t n = (size_t)*w * *h * *nc;
    if (size - 6 != 4 * n) {
        snprintf(err, errlen, "%s: %zu bytes of texels, expected %zu", name, size - 6, 4 * n);
        return 0;
    }
    *px = xmalloc(n * sizeof(float));
    memcpy(*px, d + 6, n * sizeof(float)); /* little endian, as every machine this runs on */
    return 1;
}
