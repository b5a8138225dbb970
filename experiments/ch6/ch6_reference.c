/* bin/ch6_equal's BDPT reference (ch6_equal.h): cached by common/refcache.h's rule, keyed by the
 * scene's content (its file, meshes and textures: ckpt_scene_hash) and the settings that change its
 * pixels (samples per pixel, seed, shortest length, resolution), rendered like the runs. The scene's
 * content hash is computed here once and shared with the run cache's key (ch6_scene_identity). */
#include "ch6/ch6_equal.h"
#include "common/die.h"
#include "common/glossy_mask.h"
#include "common/proc.h"
#include "common/refcache.h"
#include "io/checkpoint.h"
#include "io/image.h"
#include "path/scene_ready.h"
#include "scene/scene_hash.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#define REF_SEED "12345"

/* refcache_render_fn: render --method bdpt into path. Rendered under another name and renamed
 * when complete: an interrupted render writes a partial image, which must never pass for the
 * cached reference. */
static struct image *render_reference(void *ctx, const char *path, char *err, size_t errlen)
{
    struct ch6_equal *e = ctx;
    char part[1200], spp_s[32], exr[1300];
    fprintf(stderr, "%s: rendering the BDPT reference (%d spp) into %s\n", e->prog, e->refspp, path);
    snprintf(part, sizeof part, "%.*s.rendering", (int)(strlen(path) - 4), path);
    snprintf(spp_s, sizeof spp_s, "%d", e->refspp);
    char *rv[24] = {e->render,   (char *)e->scene, "--method", "bdpt",         "--spp",     spp_s,   "--seed", REF_SEED,
                    "--threads", e->thr,           "--quiet",  "--min-length", e->minlen_s, "--out", part};
    int c = 15;
    if (e->res) rv[c++] = "--resolution", rv[c++] = (char *)e->res;
    if (e->maxlen) rv[c++] = "--max-length", rv[c++] = e->maxlen_s;
    if (proc_render_resumable(e->prog, &e->renderer, rv, c, part, e->ckpt_every, NULL) != 0)
        die(DIE_RUNTIME, e->prog, "the reference render failed: %s", path);
    snprintf(exr, sizeof exr, "%s.exr", part);
    if (rename(exr, path) != 0) die(DIE_RUNTIME, e->prog, "cannot rename the reference into place: %s", path);
    snprintf(exr, sizeof exr, "%s.png", part); /* the render's PNG: OUT/reference.png replaces it */
    unlink(exr);
    snprintf(exr, sizeof exr, "%s.csv", part); /* and its samples and time, which the key does not need */
    unlink(exr);
    return img_read(path, err, errlen);
}

void ch6_scene_identity(struct ch6_equal *e)
{
    if (!e->refspp && !e->run_cache_dir) return;
    char err[4200];
    struct scene *sc = scene_load(e->scene, err, sizeof err);
    if (!sc) die(DIE_USAGE, e->prog, "%s", err);
    e->scene_hash = ckpt_scene_hash(sc);
    if (e->res) camera_resize(&sc->cam, e->res_wh[0], e->res_wh[1]);
    if (e->refspp) e->glossy = glossy_mask(sc, &e->nglossy);
    e->glossy_w = sc->cam.width, e->glossy_h = sc->cam.height;
    scene_free(sc);
    if (e->run_cache_dir && !e->renderer.path) /* in-process runs: this executable renders them */
        e->cache = (struct run_cache){.dir = e->run_cache_dir, .build = ckpt_build_hash(), .scene = e->scene_hash};
    if (e->cache.dir && !e->cache.build)
        die(DIE_RUNTIME, e->prog,
            "--run-cache: cannot read the running executable (/proc/self/exe) to identify the build");
}

/* OUT/glossy-mask.png: the reference with the pixels off the glossy surfaces dimmed to a fifth, to
 * show where the glossy statistics are measured. */
static void write_glossy_png(const struct ch6_equal *e)
{
    if (!e->ref || !e->nglossy || e->ref->w != e->glossy_w || e->ref->h != e->glossy_h) return;
    char err[4200], path[4096];
    struct image *m = img_create(e->ref->w, e->ref->h);
    for (size_t i = 0; i < (size_t)m->w * m->h; i++)
        for (int c = 0; c < 3; c++)
            m->px[3 * i + c] = e->ref->px[3 * i + c] * (e->glossy[i] ? 1 : 0.2);
    snprintf(path, sizeof path, "%s/glossy-mask.png", e->out);
    bool ok = img_write_png(m, e->expo, path, err, sizeof err);
    img_destroy(m);
    if (!ok) die(DIE_RUNTIME, e->prog, "%s", err);
}

void ch6_reference(struct ch6_equal *e)
{
    char err[4200], settings[256], path[4096], maxs[32] = "";
    e->ref = NULL;
    if (e->refspp) {
        if (e->maxlen) snprintf(maxs, sizeof maxs, "-max%d", e->maxlen); /* absent: the default, as before */
        if (!e->refpath) {
            snprintf(e->defref, sizeof e->defref, "results/reference/%s-bdpt-%s-min%d%s-%d.exr", e->scene_name,
                     e->res ? e->res : "native", e->minlen, maxs, e->refspp);
            e->refpath = e->defref;
        }
        snprintf(settings, sizeof settings, "bdpt spp=%d seed=%s min_length=%d resolution=%s%s%s", e->refspp, REF_SEED,
                 e->minlen, e->res ? e->res : "native", e->maxlen ? " max_length=" : "", e->maxlen ? e->maxlen_s : "");
        struct refcache rc = {.path = e->refpath, .scene_hash = e->scene_hash, .settings = settings};
        e->ref = refcache_get(&rc, render_reference, e, err, sizeof err);
        if (!e->ref) die(DIE_RUNTIME, e->prog, "%s", err);
    }
    e->mlum = e->ref ? img_mean_luminance(e->ref) : NAN;
    e->eps = 0.01 * e->mlum * e->mlum;
    e->expo = 0.5 / e->mlum;
    if (e->ref && !(e->mlum > 0)) die(DIE_RUNTIME, e->prog, "the reference is black: %s", e->refpath);
    snprintf(path, sizeof path, "%s/reference.png", e->out);
    if (e->ref && !img_write_png(e->ref, e->expo, path, err, sizeof err)) die(DIE_RUNTIME, e->prog, "%s", err);
    write_glossy_png(e);
}
