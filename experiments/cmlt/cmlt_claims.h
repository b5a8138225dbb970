/* The CMLT paper's Table 1 claims (§5) tested on the toy's measured RMSE: per budget, one row per
 * ordering the paper states, verdicts from common/verdict.h, written as claims.csv and claims.md. */
#ifndef CMLT_CLAIMS_H
#define CMLT_CLAIMS_H

#include "cmlt/cmlt_mcmc.h"
#include <stddef.h>
#include <stdint.h>

#define CMLT_MAX_BUDGETS 4

struct cmlt_claims_in {
    const char *dir, *scale, *command;
    int seeds, nbudgets;
    const uint64_t *budgets;
    const double (*mean)[CMLT_NALGO], (*se)[CMLT_NALGO]; /* [budget][algorithm]: RMSE over seeds */
    /* [0 mean, 1 standard error][budget][algorithm] over seeds: the mean acceptance probability of a
     * step, and steps per second (the seed pass's time included) */
    const double (*acc)[CMLT_MAX_BUDGETS][CMLT_NALGO], (*rate)[CMLT_MAX_BUDGETS][CMLT_NALGO];
};

/* Writes DIR/claims.csv and claims.md; returns the Markdown (caller frees) or NULL with err set. */
char *cmlt_write_claims(const struct cmlt_claims_in *in, char *err, size_t errlen);

#endif
