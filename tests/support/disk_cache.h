/* Results several tests need, computed once per build and kept on disk (build/tests/disk-cache/):
 * references that split tests share, and that suites comparing against the same reference read
 * instead of rendering again. A result is found by what makes it: the test runner's own bytes (a
 * rebuild invalidates everything), the loaded scene (ckpt_scene_hash: camera size and filter
 * count), the Embree kernel asked for, and the caller's description of every setting. */
#ifndef DISK_CACHE_H
#define DISK_CACHE_H

#include "support/agree.h"
#include <stddef.h>
#include <stdint.h>

/* Fills buf (n bytes) with make(buf, ctx), or with what an earlier call of the same key stored.
 * Concurrent tests asking for the same key wait for the first one's result instead of repeating
 * it. sc may be NULL for results that read no scene. */
void disk_cached(void *buf, size_t n, const struct scene *sc, const char *settings, void (*make)(void *buf, void *ctx),
                 void *ctx);

/* stack_runs(out, render, ctx, reps, seed0, blk) through disk_cached: `settings` must name every
 * option of the render ctx stands for (method, spp, lengths, ...); reps, seed0 and blk are added. */
void stack_runs_cached(struct stack *out, render_fn render, void *ctx, int reps, uint64_t seed0, int blk,
                       const struct scene *sc, const char *settings);

#endif
