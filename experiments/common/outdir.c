/* Output folders (outdir.h). */
#include "common/outdir.h"
#include "common/die.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* One level: an existing directory is success, an existing file is ENOTDIR. */
static int make_one(const char *path)
{
    if (mkdir(path, 0777) == 0) return 0;
    int e = errno;
    struct stat st;
    if (e == EEXIST) return stat(path, &st) == 0 && S_ISDIR(st.st_mode) ? 0 : ENOTDIR;
    return e;
}

bool outdir_make(const char *dir, char *err, size_t errlen)
{
    if (!dir || !*dir) {
        snprintf(err, errlen, "cannot create '': empty folder name");
        return false;
    }
    char *p = strdup(dir);
    if (!p) {
        snprintf(err, errlen, "cannot create %s: %s", dir, strerror(ENOMEM));
        return false;
    }
    int e = 0;
    /* each prefix ending before a '/', then the whole path */
    for (char *s = p + 1; !e && *s; s++)
        if (*s == '/' && s[-1] != '/') {
            *s = 0;
            e = make_one(p);
            if (e) snprintf(err, errlen, "cannot create %s: %s", p, strerror(e));
            *s = '/';
        }
    if (!e) {
        e = make_one(p);
        if (e) snprintf(err, errlen, "cannot create %s: %s", p, strerror(e));
    }
    free(p);
    return !e;
}

void outdir_require(const char *prog, const char *dir)
{
    char err[4200];
    if (!outdir_make(dir, err, sizeof err)) die(DIE_USAGE, prog, "%s", err);
}

bool outdir_make_parent(const char *file, char *err, size_t errlen)
{
    const char *sl = strrchr(file, '/');
    if (!sl || sl == file) return true;
    char dir[4096];
    snprintf(dir, sizeof dir, "%.*s", (int)(sl - file), file);
    return outdir_make(dir, err, errlen);
}
