/* bin/render's command line: what one run is asked to do (render_args.c), shared by the run
 * (render_run.c) and the writers of its outputs (render_write.c). */
#ifndef RENDER_ARGS_H
#define RENDER_ARGS_H

#include "mc/render.h"
#include "mcmc/mlt.h"
#include <stdbool.h>
#include <stddef.h>

struct scene;

struct render_args {
    const char *scene, *out, *resume, *method;
    double checkpoint, cpu_seconds;
    struct render_opts mc;
    struct mlt_opts mlt;
    int res[2], sampler;
    const char *res_arg; /* --resolution as given */
    bool quiet, timing;
    /* --timing: wall-clock seconds at each phase's end (render_run.c) */
    struct {
        double startup, main, loaded, rendered, written, seed_pass;
    } t;
};

/* Reads argv into a (set to its defaults first by the caller); --help prints and exits 0, a bad
 * option is one line and exit 2 (common/opts.h). */
void render_args_parse(int argc, char **argv, struct render_args *a);
/* What the MCMC methods take from the shared options and the scene. */
void render_args_mlt_setup(struct mlt_opts *m, const struct render_args *a, const struct scene *sc);
/* Every option that changes the numbers a run produces, as one line: a checkpoint resumes only
 * under the same. The MCMC options must be set (render_args_mlt_setup) before. */
void render_args_identity(const struct render_args *a, const struct scene *sc, char *buf, size_t n);
/* The small steps' names (core/mcmc/mlt_options.c). */
const char *render_small_step_name(enum small_step k);

#endif
