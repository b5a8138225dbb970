/* bin/fig6_1's measurements as its claims read them (fig6_1.c fills them), and the thesis's
 * statements on Figure 6.1 and on PITP's moves (§5.2, §5.2.1, §6.1) with their verdicts:
 * OUT/claims.csv and claims.md. */
#ifndef FIG6_1_CLAIMS_H
#define FIG6_1_CLAIMS_H

#include "sampler/sampler.h"
#include <stdbool.h>
#include <stddef.h>

enum { FIG6_1_RUNS = 4 }; /* independent runs per method: the claims' errors are over them */

/* Per method (0 MMLT, 1 PITP), length and technique changed: the mean of the runs' mean
 * acceptances and its standard error; have = the cell was written. */
struct fig6_1_cells {
    double mean[2][MAX_PATH_LENGTH + 1][2], se[2][MAX_PATH_LENGTH + 1][2];
    bool have[2][MAX_PATH_LENGTH + 1][2];
    /* PITP's perturbations per length: [0] the share with j != i, [1] the mean |j - i| of those, [2] the
     * mean acceptance; each the mean over the runs and its standard error ([.][k][1] = 0: no runs) */
    double moves[3][MAX_PATH_LENGTH + 1][2];
    int K;
};

/* claims.csv and claims.md in out; their Markdown (the caller frees), or NULL with a message in err. */
char *fig6_1_claims(const struct fig6_1_cells *t, const char *out, const char *scale, char *err, size_t errlen);

#endif
