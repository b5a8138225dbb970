/* The Monte Carlo render driver: pixels in rows dealt round-robin to threads, one sampler stream
 * per camera sample, per-thread framebuffers merged in thread order. For a given seed and thread
 * count the image is bitwise reproducible; it also does not depend on the thread count except
 * through the summation order of light-tracing splats. Over MPI ranks (core/base/dist.h) rows go to the
 * job's global threads, so N ranks of T threads give the image of one process of N * T threads; the
 * image and stats are the job's on rank 0 only. A time budget's passes are decided by rank 0, on the
 * slowest rank's clock, for all ranks.
 * With a time budget (equal-time comparisons) the image is rendered in passes of one sample per
 * pixel, each pass started only if, at the mean pass time so far, it ends within the budget; the
 * image is then reproducible for the number of passes it reached. */
#ifndef RENDER_H
#define RENDER_H

#include "io/checkpoint.h"
#include "io/image.h"
#include "mc/bdpt_tech.h"
#include "path/splat.h"
#include "scene/scene.h"
#include <stdint.h>

enum method { METHOD_PT, METHOD_BDPT };

struct render_opts {
    enum method method;
    int spp;
    double seconds; /* > 0: instead of spp, whole passes of one sample per pixel while they fit */
    bool cpu_time;  /* seconds are CPU seconds per thread (budget_seconds, parallel.h) */
    uint64_t seed;
    int threads;
    int max_length;
    int min_length; /* paths shorter than this (segments) are left out */
    bool progress;
    int only_s, only_t; /* BDPT: one technique, unweighted (only_t > 0) */
    bool sobol;         /* scrambled (0,2)-sequences instead of independent numbers (sampler/sobol02.h) */
    int tech_k;         /* BDPT: > 0, per-technique images of this path length (render_stats.tech) */
    /* Checkpoints (checkpoint.h): periodic, at an interruption, and resuming. With a spp budget
     * a resumed run ends bit-identical to an uninterrupted one; with a time budget it continues
     * the passes with what the budget had left. */
    struct ckpt_ctl *ckpt;
};

struct render_stats {
    long samples;
    int spp; /* samples per pixel taken (the passes of a time-budgeted run) */
    double seconds;
    long nonfinite;                 /* samples' contributions dropped as NaN or infinite */
    struct nonfinite nonfinite_len; /* the same by path length (path/splat.h) */
    bool partial;           /* interrupted: rows not reached (in the last pass, under a time budget) lack samples */
    bool resume_failed;     /* the checkpoint's state did not fit this run: nothing was rendered */
    struct bdpt_tech *tech; /* with tech_k: the job's per-technique sums (mc/bdpt_tech.h; caller frees) */
};

/* Returns the image in final units (average radiance per pixel). */
struct image *render_mc(const struct scene *sc, const struct render_opts *o, struct render_stats *st);
const char *method_name(enum method m);
bool method_parse(const char *s, enum method *m);

#endif
