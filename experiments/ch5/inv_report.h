/* bin/inverse_density's outputs: OUT/inverse_density.csv (one row per function), its Markdown
 * table OUT/inverse_density.md, and the claims files with claim T21's row, decided by every
 * function's two p-values (chi-square, KS) at family-wise alpha = 0.01, Sidak-corrected. */
#ifndef INV_REPORT_H
#define INV_REPORT_H

#include "ch5/inv_run.h"

#define INV_ALPHA 0.01

struct inv_cfg {
    const char *prog, *scale, *out;
    uint64_t seed;
    int threads;
    long samples, path_samples;
    const char *bsdf_scenes, *path_scenes;
    const char *broken;
    bool require_holds;
};

/* Writes the files (an unwritable one: one line and exit status 1) and prints the Markdown table
 * and claims on stderr; returns whether no function rejects. */
bool inv_report(const struct inv_cfg *c, const struct inv_func *f, const struct inv_result *r, int n);

#endif
