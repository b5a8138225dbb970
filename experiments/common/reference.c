/* In-process references through the reference cache (reference.h). */
#include "common/reference.h"
#include "common/refcache.h"
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
};

/* refcache_render_fn: the reference at the spec's fixed seed, written to path atomically. */
static struct image *render_reference(void *ctx, const char *path, char *err, size_t errlen)
{
    const struct reference_job *j = ctx;
    const struct reference_spec *s = j->spec;
    fprintf(stderr, "%s: rendering the %s reference (%d spp, %dx%d) into %s\n", j->prog, method_name(s->method), s->spp,
            j->sc->cam.width, j->sc->cam.height, path);
    struct render_opts o = {.method = s->method,
                            .spp = s->spp,
                            .seed = s->seed,
                            .threads = s->threads,
                            .max_length = s->max_length,
                            .progress = isatty(2)};
    struct render_stats st;
    struct image *ref = render_mc(j->sc, &o, &st);
    if (!img_write_exr(ref, 1, path, err, errlen)) {
        img_destroy(ref);
        return NULL;
    }
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
    return refcache_get(&rc, render_reference, &(struct reference_job){prog, sc, spec}, err, errlen);
}
