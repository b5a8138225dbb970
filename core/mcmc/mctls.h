/* The multiple correlated-try large step of MMLT (thesis §4.3, Eq. 4.1-4.7): trace both subpaths
 * of fresh numbers to length k, take all k + 1 of their connections as the trials, pick one in
 * proportion to its target (sampling/pick.h) and accept with the generalised ratio
 * min(1, sum_i pi(y_i) / sum_i pi(x_i)) (Eq. 4.7), the denominator the current numbers' own k + 1
 * connections. Chosen for every length (LARGE_MCTLS) or from hybrid_length on (LARGE_HYBRID). */
#ifndef MCTLS_H
#define MCTLS_H

#include "io/image.h"
#include "mc/integrator.h"
#include "mcmc/chain.h"
#include "mcmc/mlt.h"

/* The most trials mlt_opts.mctls_tries may ask for. */
#define MCTLS_MAX_TRIES 64

/* Per-thread buffers: the targets and splats of the k + 1 trials, for the proposal and for the
 * current numbers (index t = 1..k+1). */
struct mctls_buf {
    double pi[MAX_PATH_LENGTH + 2], xpi[MAX_PATH_LENGTH + 2];
    struct splat_list sp[MAX_PATH_LENGTH + 2], xsp[MAX_PATH_LENGTH + 2];
};

/* Whether the large steps of length k are MCTLS's under these options. */
bool use_mctls(const struct mlt_opts *o, int k);

/* The trials (Eq. 4.7's terms): the targets of all k + 1 techniques of the subpaths the sampler's
 * numbers give, traced to full length; pi[t] and sp[t] for t = 1..k+1 (w counts the connections).
 * Returns their sum. */
double mctls_trials(const struct path_ctx *pc, struct sampler *s, struct scratch *w, int k, double *pi,
                    struct splat_list *sp);

/* Eq. 4.7's acceptance probability from the sums of the proposal's and the current trials' targets. */
double mctls_accept(double ysum, double xsum);

/* One MCTLS proposal for chain c, splatted with expected values into img (r: the thread's
 * generator, for the pick, the acceptance, the new technique number and drawn trials; o: the
 * trials, mctls_tries and mctls_count_t0). Returns the acceptance
 * probability; *acc: accepted, *changed: the picked technique differs from the chain's, *nonzero:
 * any trial contributes. On acceptance the chain's path (c->x, PITP) is the picked technique's. */
double mctls_step(const struct path_ctx *pc, const struct mlt_opts *o, struct chain *c, struct scratch *w,
                  struct mctls_buf *b, rng *r, struct image *img, bool *acc, bool *changed, bool *nonzero);

#endif
