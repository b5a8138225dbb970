/* Allocation that cannot fail silently, assertions and atomic file writes (util.h). */
#include "base/util.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static void oom(size_t n)
{
    fprintf(stderr, "out of memory allocating %zu bytes\n", n);
    abort();
}

void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p) oom(n);
    return p;
}

void *xcalloc(size_t n, size_t size)
{
    void *p = calloc(n ? n : 1, size ? size : 1);
    if (!p) oom(n * size);
    return p;
}

void *xrealloc(void *p, size_t n)
{
    void *q = realloc(p, n ? n : 1);
    if (!q) oom(n);
    return q;
}

bool file_is_regular(FILE *f)
{
    struct stat st;
    return fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode);
}

void str_sanitize(char *s)
{
    for (; *s; s++)
        if ((unsigned char)*s < 32 || *s == 127) *s = '?';
}

char *xstrdup(const char *s)
{
    size_t n = strlen(s) + 1;
    return memcpy(xmalloc(n), s, n);
}

void die_assert(const char *expr, const char *file, int line)
{
    fprintf(stderr, "%s:%d: assertion failed: %s\n", file, line, expr);
    abort();
}

bool atomic_write(const char *path, write_fn write, void *ctx, char *err, size_t errlen)
{
    /* Keep the extension last: OpenImageIO picks the format from it. */
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    size_t dirlen = (size_t)(base - path);
    size_t n = strlen(path) + 32;
    char *tmp = xmalloc(n);
    snprintf(tmp, n, "%.*s.tmp%ld-%s", (int)dirlen, path, (long)getpid(), base);
    bool ok = write(tmp, ctx, err, errlen);
    if (ok && rename(tmp, path) != 0) {
        snprintf(err, errlen, "%s: cannot rename temporary file into place", path);
        ok = false;
    }
    if (!ok) remove(tmp);
    free(tmp);
    return ok;
}

static bool write_text(const char *tmp, void *ctx, char *err, size_t errlen)
{
    FILE *f = fopen(tmp, "w");
    if (!f) {
        snprintf(err, errlen, "%s: cannot write", tmp);
        return false;
    }
    bool ok = fputs((const char *)ctx, f) >= 0;
    ok = (fclose(f) == 0) && ok;
    if (!ok) snprintf(err, errlen, "%s: write failed", tmp);
    return ok;
}

bool write_text_atomic(const char *path, const char *text, char *err, size_t errlen)
{
    return atomic_write(path, write_text, (void *)text, err, errlen);
}

char *read_whole_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = n >= 0 ? xmalloc((size_t)n + 1) : NULL;
    size_t r = s ? fread(s, 1, (size_t)n, f) : 0;
    if (s) s[r] = 0;
    fclose(f);
    return s;
}
