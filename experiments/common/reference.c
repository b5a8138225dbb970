/* In-process references through the reference cache (reference.h). */
#include "common/reference.h"
#include "common/refcache.h"
#include "io/checkpoint.h"
#include "io/image.h"
#include "scene/scene.h"
#include "scene/scene_hash.h"
#include <stdio.h>
#include <unistd.h>

/* What the render needs (refcache_render_fn's ctx). */
struct reference_job {
    const char *prog;
    const struct scene *sc;
    const struct reference_spec *spec;
    const char *settings; /* the cache's settings line: the checkpoint's identity too */
};

/* The checkpoint of an interrupted reference, PATH.rendering.ckpt, into *payload when it is one of
 * this reference (same build, scene and settings); otherwise the reference starts afresh. */
static void resume_from(const struct reference_job *j, struct ckpt_ctl *ctl, struct ckpt_buf *payload)
{
    char why[512];
    if (access(ctl->path, F_OK) != 0) return;
    if (ckpt_read_file(ctl->path, &ctl->id, payload, why, sizeof why)) {
        ctl->resume = payload;
        fprintf(stderr, "%s: continuing the reference from %s\n", j->prog, ctl->path);
    } else {
        fprintf(stderr, "%s: %s; rendering the reference afresh\n", j->prog, why);
    }
}

/* refcache_render_fn: the reference at the spec's fixed seed, written to path atomically. It
 * checkpoints every minute into PATH.rendering.ckpt, which a killed run's rerun continues (a
 * 4096-spp full-scale reference takes half an hour on two cores); an interrupted render writes no
 * reference. */
static struct image *render_reference(void *ctx, const char *path, char *err, size_t errlen)
{
    const struct reference_job *j = ctx;
    const struct reference_spec *s = j->spec;
    fprintf(stderr, "%s: rendering the %s reference (%d spp, %dx%d) into %s\n", j->prog, method_name(s->method), s->spp,
            j->sc->cam.width, j->sc->cam.height, path);
    char ckpath[4200], id[320];
    snprintf(ckpath, sizeof ckpath, "%s.rendering.ckpt", path);
    snprintf(id, sizeof id, "%s threads=%d", j->settings, s->threads); /* each thread's state is its own */
    struct ckpt_ctl ctl = {.path = ckpath, .every = 60, .id = {ckpt_build_hash(), ckpt_scene_hash(j->sc), id}};
    struct ckpt_buf payload = {0};
    resume_from(j, &ctl, &payload);
    struct render_opts o = {.method = s->method,
                            .spp = s->spp,
                            .seed = s->seed,
                            .threads = s->threads,
                            .max_length = s->max_length,
                            .progress = isatty(2),
                            .ckpt = &ctl};
    struct render_stats st;
    struct image *ref = render_mc(j->sc, &o, &st);
    if (st.resume_failed) { /* a checkpoint of this identity that does not fit: start afresh */
        img_destroy(ref);
        ctl.resume = NULL;
        ref = render_mc(j->sc, &o, &st);
    }
    ckpt_buf_free(&payload);
    if (st.partial || ctl.err[0]) {
        snprintf(err, errlen, "the reference %s was %s", path,
                 ctl.err[0] ? ctl.err : "interrupted (its checkpoint stays)");
        img_destroy(ref);
        return NULL;
    }
    if (!img_write_exr(ref, 1, path, err, errlen)) {
        img_destroy(ref);
        return NULL;
    }
    unlink(ckpath);
    return ref;
}

struct image *reference_render_cached(const char *prog, const struct scene *sc, const struct reference_spec *spec,
                                      char *err, size_t errlen)
{
    char settings[256];
    snprintf(settings, sizeof settings, "%s spp=%d seed=%llu max_length=%d resolution=%dx%d", method_name(spec->method),
             spec->spp, (unsigned long long)spec->seed, spec->max_length, sc->cam.width, sc->cam.height);
    struct refcache rc = {.path = spec->path, .scene_hash = ckpt_scene_hash(sc), .settings = settings};
    struct image *ref = refcache_load(&rc);
    if (ref) {
        fprintf(stderr, "%s: using cached reference %s\n", prog, spec->path);
        return ref;
    }
    return refcache_get(&rc, render_reference, &(struct reference_job){prog, sc, spec, settings}, err, errlen);
}
