/* The reference cache (refcache.h). */
#include "common/refcache.h"
#include "base/util.h"
#include "common/outdir.h"
#include "io/checkpoint.h"
#include "io/image.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void refcache_key(const struct refcache *rc, char *key, size_t n)
{
    snprintf(key, n, "reference-v1 scene=%016llx %s\n", (unsigned long long)rc->scene_hash, rc->settings);
}

void refcache_key_path(const char *path, char *out, size_t n)
{
    size_t len = strlen(path);
    if (len > 4 && !strcmp(path + len - 4, ".exr"))
        snprintf(out, n, "%.*s.key", (int)(len - 4), path);
    else
        snprintf(out, n, "%s.key", path);
}

struct image *refcache_load(const struct refcache *rc)
{
    char key[4096], kpath[4200], err[1024];
    refcache_key(rc, key, sizeof key);
    refcache_key_path(rc->path, kpath, sizeof kpath);
    char *have = read_whole_file(kpath);
    bool match = have && !strcmp(have, key);
    free(have);
    return match ? img_read(rc->path, err, sizeof err) : NULL;
}

struct image *refcache_get(const struct refcache *rc, refcache_render_fn render, void *ctx, char *err, size_t errlen)
{
    struct image *im = refcache_load(rc);
    if (im) return im;
    char key[4096], kpath[4200];
    refcache_key(rc, key, sizeof key);
    refcache_key_path(rc->path, kpath, sizeof kpath);
    if (!outdir_make_parent(rc->path, err, errlen)) return NULL;
    unlink(kpath); /* the image is about to change: its old key must not outlive it */
    im = render(ctx, rc->path, err, errlen);
    if (im && !write_text_atomic(kpath, key, err, errlen)) {
        img_destroy(im);
        return NULL;
    }
    return im;
}
