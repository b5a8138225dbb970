/* Runs shared between studies. Several studies render runs that are the same render: the equal-time
 * figure's MMLT is the MMLT of the MMLT-design study, mmlt-fig4's BDPT, PSSMLT and MMLT are
 * mmlt-equal's. At full scale such a run is a minute of both cores; the cache renders it once.
 *
 * A run is identified by what decides its outputs: the renderer's build (a hash of the executable
 * that renders in-process, so that a rebuild after any change to the code, committed or not, never
 * reuses a run of the old code), the scene's content (ckpt_scene_hash: file, meshes, textures), and
 * bin/render's options in a canonical order (an option and its values as one item, sorted by the
 * option's name, stably, so a repeated option keeps its order; the scene's path and the options
 * that only say where and how to write, --out, --quiet, --checkpoint and --resume, left out, and so
 * is an MCMC option given once at its default, mcmc/mlt_options.h: "--method mmlt" and "--method
 * mmlt --p-large 0.1" are one render). That
 * text is the key; the entry is DIR/<64-bit hash of the key>/ holding the key and the run's files
 * (PREFIX.exr, .csv, .png, .log, .mixing.csv, ...), hard links where the file system allows, so a
 * cached run costs no space beside the study's copy.
 *
 *   struct run_cache rc = {.dir = "results/run-cache", .build = ckpt_build_hash(),
 *                          .scene = ckpt_scene_hash(sc)};
 *   run_cache_key(&rc, argv, argc, key, sizeof key);
 *   if (!run_cache_fetch(&rc, key, prefix)) { render argv; run_cache_store(&rc, key, prefix, ...); }
 *
 * A fetched run is the same render, not a new sample: two studies that share it are correlated in
 * that run, which is what makes it cheaper; within one study every run is still its own. */
#ifndef RUN_CACHE_H
#define RUN_CACHE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

struct run_cache {
    const char *dir; /* NULL: no cache */
    uint64_t build;  /* the renderer's executable (ckpt_build_hash, io/checkpoint.h) */
    uint64_t scene;  /* the scene's content */
};

/* The key text of the render command argv[0..argc-1] (argv[0] the program, argv[1] the scene);
 * false when it does not fit in n. */
bool run_cache_key(const struct run_cache *rc, char *const *argv, int argc, char *key, size_t n);

/* The cached run of `key`, linked (or copied) to PREFIX.* in place of whatever is there; false when
 * the cache has no complete entry whose key file says exactly `key`. */
bool run_cache_fetch(const struct run_cache *rc, const char *key, const char *prefix);

/* A completed run's files PREFIX.* (checkpoints and temporaries left out) into the entry of `key`,
 * made under a temporary name and renamed into place; an entry already there is kept. False with a
 * message in err when the entry cannot be made. */
bool run_cache_store(const struct run_cache *rc, const char *key, const char *prefix, char *err, size_t errlen);

#endif
