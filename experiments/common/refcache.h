/* The reference cache: one rule for every tool. A reference image is cached as PATH (an EXR) with
 * its key beside it in PATH with .key for .exr; the key is the scene's content (a 64-bit hash) and
 * every setting that changes the reference's pixels (as text). The cached image is used when the
 * key file says exactly the current key; otherwise it is rendered again, and the key is written
 * only after the image, so an interrupted render never leaves a key over a stale image.
 *
 *   struct refcache rc = {.path = "results/reference/ajar-bdpt-native-min3-256.exr",
 *                         .scene_hash = ckpt_scene_hash(sc),
 *                         .settings = "bdpt spp=256 seed=12345 min_length=3 resolution=native"};
 *   struct image *ref = refcache_get(&rc, render_it, ctx, err, sizeof err);
 *
 * scene_hash: scene/scene_hash.h's ckpt_scene_hash of the loaded scene, which covers its meshes and
 * textures too (a checkpoint's scene identity is the same hash). */
#ifndef REFCACHE_H
#define REFCACHE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

struct image;

struct refcache {
    const char *path;     /* the cached EXR */
    uint64_t scene_hash;  /* the scene's content */
    const char *settings; /* method, samples, seed, lengths, resolution, ...: one line of text */
};

/* Renders the reference and writes it to path (complete, or not at all: render under another name
 * and rename it into place); returns the image, or NULL with a message in err. */
typedef struct image *(*refcache_render_fn)(void *ctx, const char *path, char *err, size_t errlen);

/* The key text of rc, one line ending in '\n'. */
void refcache_key(const struct refcache *rc, char *key, size_t n);
/* The key file's path (PATH with .key for .exr, else PATH.key). */
void refcache_key_path(const char *path, char *out, size_t n);
/* The cached image when its key matches (NULL otherwise, also when it cannot be read). */
struct image *refcache_load(const struct refcache *rc);
/* The cached image, or render(ctx, ...)'s after making the path's folder; the key is then written.
 * NULL with a message in err when the folder, the render or the key cannot be made. */
struct image *refcache_get(const struct refcache *rc, refcache_render_fn render, void *ctx, char *err, size_t errlen);

#endif
