/* What bin/fig5_5 and bin/fig5_6 share: their options, one MMLT run of either small step on the
 * jewelry scene, and image output. */
#ifndef FIG5_COMMON_H
#define FIG5_COMMON_H

#include "common/opts.h"
#include "common/table_set.h"
#include "mcmc/mlt.h"
#include <stdio.h>

struct fig5_cfg {
    const char *prog;
    struct opts_figure fig; /* scene, scale, seed, threads, out */
    int width, height, seeds, max_length;
    long mpp, seed_paths;
    double p_large;
};

/* Parses the shared options (opts.h: OPTS_FIGURE, --resolution, --mpp, --seeds; `about` follows the
 * usage line of --help); the scale presets fill what was not given. c->prog and c->fig.out (the
 * default folder) are set first. */
void fig5_parse(int argc, char **argv, struct fig5_cfg *c, const char *about);
/* The metadata lines (csv_meta.h) the figures share: at the top, "# TITLE", scene, commit, scale,
 * "# resolution WxH", "# mutations_per_pixel N"; fig5_meta_runs: "# seeds N from S", "# threads T". */
void fig5_meta_head(FILE *f, const struct fig5_cfg *c, const char *title);
void fig5_meta_runs(FILE *f, const struct fig5_cfg *c);
/* Loads the scene at the configured resolution (exits with one error line on failure). */
struct scene *fig5_scene(const struct fig5_cfg *c);
/* One MMLT run: Gaussian kernel (sigma 1/64) for both small-step kinds, same everything else. */
void fig5_run(const struct scene *sc, const struct fig5_cfg *c, enum small_step kind, uint64_t seed, bool angle,
              struct mlt_result *r);
extern const char *const fig5_kind_name[3];
/* An 8-bit PNG whose grey level is linear in v / white, clamped (the thesis's "black = 0,
 * white >= 0.5 rad"); the image's first channel is used. Atomic, like every image write. */
bool fig5_write_linear_png(const struct image *im, double white, const char *path, char *err, size_t errlen);
/* Writes the tables into OUT atomically and says so on stderr (common/table_set.h); a failure is
 * the error line "PROG: ..." and exit status 1. */
void fig5_save_tables(const struct fig5_cfg *c, struct table_set *ts);

#endif
