/* Allocation that cannot fail silently, assertions and atomic file writes (util.h). */
#include "base/util.h"
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
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

static void test_stall(void)
{
    const char *e = getenv("PSS_TEST_WRITE_STALL_MS");
    long ms = e ? strtol(e, NULL, 10) : 0;
    if (ms > 0 && ms < 100000) usleep((useconds_t)(1000 * ms));
}

bool write_chunks(const char *path, const struct chunk *c, int n, char *err, size_t errlen)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    bool ok = fd >= 0;
    for (int i = 0; ok && i < n; i++) {
        if (n >= 2 && i == n / 2) test_stall();
        const char *p = c[i].p;
        for (size_t left = c[i].n; ok && left > 0;) {
            ssize_t k = write(fd, p, left);
            if (k == 0) errno = EIO; /* a regular file never takes nothing; do not spin */
            ok = k > 0;
            if (ok) p += k, left -= (size_t)k;
        }
    }
    /* a full disk may show only here: delayed allocation defers the failure to writeback */
    ok = ok && fsync(fd) == 0;
    int saved = errno;
    if (fd >= 0 && close(fd) != 0 && ok) ok = false, saved = errno;
    if (!ok) snprintf(err, errlen, "%s", strerror(saved));
    return ok;
}

/* Tests name an output in PSS_TEST_FAIL_WRITE to make its writes fail for real: the file-size
 * limit drops to 0 around them (the test ignores SIGXFSZ), as no other file may fail first. */
static bool fail_on_purpose(const char *path, struct rlimit *saved)
{
    const char *s = getenv("PSS_TEST_FAIL_WRITE");
    size_t n = s ? strlen(s) : 0, m = strlen(path);
    if (!n || n > m || strcmp(path + m - n, s) || getrlimit(RLIMIT_FSIZE, saved)) return false;
    struct rlimit zero = {0, saved->rlim_max};
    return setrlimit(RLIMIT_FSIZE, &zero) == 0;
}

/* the rename itself must reach the disk for the new file to survive a crash */
static void sync_dir(const char *path, const char *base)
{
    char *dir = base == path ? xstrdup(".") : xstrdup(path);
    if (base != path) dir[base - path] = '\0';
    int fd = open(dir, O_RDONLY | O_DIRECTORY);
    if (fd >= 0) {
        fsync(fd);
        close(fd);
    }
    free(dir);
}

bool atomic_write(const char *path, write_fn write, void *ctx, char *err, size_t errlen)
{
    /* Keep the extension last: OpenImageIO picks the format from it. */
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    size_t dirlen = (size_t)(base - path);
    size_t n = strlen(path) + 32;
    char *tmp = xmalloc(n), why[256] = "";
    snprintf(tmp, n, "%.*s.tmp%ld-%s", (int)dirlen, path, (long)getpid(), base);
    struct rlimit limit;
    bool injected = fail_on_purpose(path, &limit);
    bool ok = write(tmp, ctx, why, sizeof why);
    if (injected) setrlimit(RLIMIT_FSIZE, &limit);
    if (ok && rename(tmp, path) != 0) {
        snprintf(why, sizeof why, "rename: %s", strerror(errno));
        ok = false;
    }
    if (ok)
        sync_dir(path, base);
    else {
        remove(tmp);
        str_sanitize(why);
        bool before = access(path, F_OK) == 0;
        snprintf(err, errlen, "%s: cannot write (%s)%s", path, why[0] ? why : "reason unknown",
                 before ? "; the previous file is left as it was" : "");
    }
    free(tmp);
    return ok;
}

static bool write_chunk(const char *tmp, void *ctx, char *err, size_t errlen)
{
    return write_chunks(tmp, ctx, 1, err, errlen);
}

bool write_bytes_atomic(const char *path, const void *p, size_t n, char *err, size_t errlen)
{
    struct chunk c = {p, n};
    return atomic_write(path, write_chunk, &c, err, errlen);
}

bool write_text_atomic(const char *path, const char *text, char *err, size_t errlen)
{
    return write_bytes_atomic(path, text, strlen(text), err, errlen);
}

void *read_file_bytes(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = len >= 0 ? xmalloc((size_t)len + 1) : NULL;
    size_t r = s ? fread(s, 1, (size_t)len, f) : 0;
    bool ok = s && r == (size_t)len && !ferror(f);
    fclose(f);
    if (!ok) {
        free(s);
        return NULL;
    }
    s[r] = 0;
    *n = r;
    return s;
}

char *read_whole_file(const char *path)
{
    size_t n;
    return read_file_bytes(path, &n);
}
