/* A Monte Carlo reference image rendered in-process and cached by refcache.h's rule: the in-process
 * figure tools (chapters 4 and 5) ask for one by its settings and get the cached EXR back while the
 * scene's content (ckpt_scene_hash) and those settings are what they were, else a fresh render at
 * the fixed seed. The key beside the EXR reads
 *   reference-v1 scene=<hash> <method> spp=N seed=S max_length=K resolution=WxH
 * with the size taken from the scene's camera. */
#ifndef REFERENCE_H
#define REFERENCE_H

#include "mc/render.h"
#include <stddef.h>
#include <stdint.h>

struct image;
struct scene;

struct reference_spec {
    const char *path; /* the cached EXR; its folder is made when missing */
    enum method method;
    int spp;
    uint64_t seed;
    int max_length;
    int threads;
};

/* The reference of sc by spec, cached or rendered (a line on stderr says which, PROG: ...); NULL
 * with a message in err when it cannot be rendered or written. */
struct image *reference_render_cached(const char *prog, const struct scene *sc, const struct reference_spec *spec,
                                      char *err, size_t errlen);

#endif
