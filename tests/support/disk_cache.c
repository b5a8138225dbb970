#include "support/disk_cache.h"
#include "io/checkpoint.h"
#include "scene/scene_hash.h"
#include <dirent.h>
#include <fcntl.h>
#include <inttypes.h>
#include <libgen.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

/* Beside the runner: `make clean` removes it with the build. Files are named BUILD-KEY, BUILD the
 * runner's hash: files of earlier builds are never read, and the first write of a new build
 * removes them (prune_other_builds). */
static bool cache_dir(char *dir, size_t n)
{
    char exe[4096];
    ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (len <= 0) return false;
    exe[len] = 0;
    snprintf(dir, n, "%s/disk-cache", dirname(exe));
    return mkdir(dir, 0777) == 0 || access(dir, W_OK) == 0;
}

static uint64_t cache_key(const struct scene *sc, size_t n, const char *settings)
{
    uint64_t h = 0, s = sc ? ckpt_scene_hash(sc) : 0, len = n;
    const char *isa = getenv("PSS_EMBREE_ISA");
    h = hash64(h, &s, sizeof s);
    h = hash64(h, &len, sizeof len);
    h = hash64(h, isa ? isa : "", isa ? strlen(isa) : 0);
    return hash64(h, settings, strlen(settings));
}

static bool read_whole(const char *path, void *buf, size_t n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return false;
    bool ok = fread(buf, 1, n, f) == n && fgetc(f) == EOF;
    fclose(f);
    return ok;
}

/* Written under another name and renamed: a reader sees the whole result or none. */
static void write_whole(const char *path, const void *buf, size_t n)
{
    char tmp[4250];
    snprintf(tmp, sizeof tmp, "%s.%d", path, (int)getpid());
    FILE *f = fopen(tmp, "wb");
    if (!f) return;
    bool ok = fwrite(buf, 1, n, f) == n;
    ok = (fclose(f) == 0) && ok;
    if (!ok || rename(tmp, path) != 0) remove(tmp);
}

/* Results of other builds of the runner can never be read again. */
static void prune_other_builds(const char *dir, const char *build)
{
    DIR *d = opendir(dir);
    if (!d) return;
    char path[4400];
    for (struct dirent *e; (e = readdir(d));) {
        if (e->d_name[0] == '.' || !strncmp(e->d_name, build, strlen(build))) continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        remove(path);
    }
    closedir(d);
}

void disk_cached(void *buf, size_t n, const struct scene *sc, const char *settings, void (*make)(void *buf, void *ctx),
                 void *ctx)
{
    char dir[4096], path[4200], lock[4210];
    if (!ckpt_build_hash() || !cache_dir(dir, sizeof dir)) {
        make(buf, ctx); /* no identity to key by, or nowhere to keep it */
        return;
    }
    char build[20];
    snprintf(build, sizeof build, "%016" PRIx64 "-", ckpt_build_hash());
    snprintf(path, sizeof path, "%s/%s%016" PRIx64, dir, build, cache_key(sc, n, settings));
    snprintf(lock, sizeof lock, "%s.lock", path);
    int fd = open(lock, O_CREAT | O_RDWR, 0666);
    if (fd >= 0) flock(fd, LOCK_EX); /* a test that dies holding it releases it with its process */
    if (!read_whole(path, buf, n)) {
        make(buf, ctx);
        prune_other_builds(dir, build);
        write_whole(path, buf, n);
    }
    if (fd >= 0) close(fd);
}

struct stack_job {
    render_fn render;
    void *ctx;
    int reps, blk;
    uint64_t seed0;
};

static void make_stack(void *buf, void *p)
{
    struct stack_job *j = p;
    stack_runs(buf, j->render, j->ctx, j->reps, j->seed0, j->blk);
}

void stack_runs_cached(struct stack *out, render_fn render, void *ctx, int reps, uint64_t seed0, int blk,
                       const struct scene *sc, const char *settings)
{
    char key[512];
    snprintf(key, sizeof key, "stack_runs reps %d seed0 %" PRIu64 " blk %d: %s", reps, seed0, blk, settings);
    struct stack_job j = {render, ctx, reps, blk, seed0};
    disk_cached(out, sizeof *out, sc, key, make_stack, &j);
}
