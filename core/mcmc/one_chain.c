/* One chain over all path lengths (mlt_opts.one_chain): the alternative the MMLT paper's §4 weighs
 * against one chain per length. The state is (k, u) with target pi(k, u) = f_k(u) / sum_k b_k.
 * Small steps keep k (symmetric in u: the usual acceptance); a large step proposes a length k'
 * with the per-length chains' P(k') and fresh numbers, an independence proposal whose kernel ratio
 * T(y -> x) / T(x -> y) is P(k) / P(k'). Each kernel keeps pi, so their mixture does, and the
 * large steps reach every length the seed pass saw. */
#include "mcmc/mutation.h"

int one_chain_first(struct worker *wk)
{
    /* the pools resampled as one: a length in proportion to its pool's sum of targets, then
     * chain_start's sample within it */
    const struct run_job *j = wk->job;
    long n = wk->opts->seed_paths;
    double total = 0;
    for (int kk = 0; kk < j->nk; kk++)
        if (j->cdf[kk]) total += j->cdf[kk][n - 1];
    double u = rng_uniform(&wk->r) * total;
    int last = 0;
    for (int kk = 0; kk < j->nk; kk++) {
        if (!j->cdf[kk]) continue;
        last = kk;
        if (u < j->cdf[kk][n - 1]) break;
        u -= j->cdf[kk][n - 1];
    }
    return last;
}

void one_chain_length(struct worker *wk, struct proposal *pr)
{
    const struct run_job *j = wk->job;
    int kk = length_index(j, rng_uniform(&wk->r));
    double p_new = j->kcdf[kk + 1] - j->kcdf[kk], p_cur = j->kcdf[pr->k] - j->kcdf[pr->k - 1];
    pr->tr = p_cur / p_new;
    pr->k = kk + 1;
}
