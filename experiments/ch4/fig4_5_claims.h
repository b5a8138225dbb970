/* bin/fig4_5's runs and what it measured of them (fig4_5.c), and the thesis's statements on
 * Figure 4.5 (§4.3) with their verdicts: OUT/claims.csv and claims.md. */
#ifndef FIG4_5_CLAIMS_H
#define FIG4_5_CLAIMS_H

#include "ch4/fig4_5_trials.h"
#include "mcmc/mlt.h"
#include <stdbool.h>
#include <stddef.h>

/* The runs: the large step, MCTLS's trials (mlt_opts.mctls_tries, 0 = Eq. 4.7) and whether t = 0
 * is counted. */
enum { V_MMLT, V_MCTLS, V_TRIES1, V_TRIES1_T0, V_TRIES2, V_TRIES4, NV };
struct fig4_5_variant {
    const char *name;
    enum large_step step;
    int tries;
    bool t0;
};
extern const struct fig4_5_variant fig4_5_variants[NV];

/* Mean acceptance and its batch-means standard error per run and length. */
struct accept_table {
    double mean[NV][MAX_PATH_LENGTH + 1], se[NV][MAX_PATH_LENGTH + 1];
    double nonzero[NV][MAX_PATH_LENGTH + 1]; /* share of proposals with a contribution (any trial's, for MCTLS) */
    long attempts[NV][MAX_PATH_LENGTH + 1];
    int K;
};

/* The ratio of run a's acceptance to run b's at length k and its standard error (first-order). */
void fig4_5_ratio(const struct accept_table *t, int a, int b, int k, double *r, double *se);
/* MCTLS's share of proposals with a contribution over MMLT large steps' at length k, with its
 * standard error: a large step's proposal does not depend on the state, so both are binomial. */
void fig4_5_light_ratio(const struct accept_table *t, int k, double *r, double *se);

/* Writes OUT/claims.csv and claims.md and returns the Markdown (caller frees), or NULL with one
 * line in err. The errors are one run's batch-means errors, so "seeds_needed" counts runs of this
 * budget. */
char *fig4_5_claims(const struct accept_table *t, const struct trials_table *tr, const char *out, const char *scale,
                    char *err, size_t errlen);

#endif
