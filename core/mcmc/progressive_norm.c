/* The large steps' estimate of the normalisation, and the progressive normalisation of the MMLT
 * paper's §4 (mlt_opts.progressive_norm): b_k from the seed pass and the large steps pooled.
 *
 * Every large step of fresh numbers draws its length's state from the same uniform distribution as
 * the seed pass does, so its target is an independent, unbiased sample of b_k; a run of N
 * mutations at p_large makes ~p_large N of them, far more than a seed pass affords (at full scale
 * ~10^7 against 10^6). The pooled mean (n_seed b_seed + sum of the large targets) / (n_seed + n) has
 * fixed weights, so it is unbiased too.
 *
 * Why the image can take it exactly: each length-k chain's splats all carry one factor, its scale
 * b_k / P(k) (splat_ev.h), so its image is (b_k / P(k)) H_k with H_k what the chain visited. Kept
 * apart per length, H_k is rescaled at the end by b_k(pooled) / b_k(seed), which is the image the
 * chain would have made had it known b_k(pooled) from the start; P(k) stays the probability the
 * chain was actually picked with. The estimate is correlated with H_k (the large steps also move the
 * chain), which makes the product biased by O(1 / n), as the seed pass's pool is correlated with
 * the chains' starts; both vanish as the run grows. A length the seed pass never saw (its estimate
 * 0, b_k > 0: the paper's "rare bounces") runs on a provisional b_k (seed_pass.c), so that its
 * large steps can find it; its image is rescaled from that. */
#include "base/dist.h"
#include "mcmc/mlt_internal.h"
#include <math.h>
#include <string.h>

/* The large steps' sums over this rank's threads, then over every rank (each rank needs them to
 * rescale its own threads' images). */
static void large_sums(const struct run_job *rj, double *sum, double *sq, long *n, long *it, long *zero)
{
    int K = rj->nk + 1;
    memset(sum, 0, (size_t)K * sizeof *sum);
    memset(sq, 0, (size_t)K * sizeof *sq);
    memset(n, 0, (size_t)K * sizeof *n);
    memset(it, 0, (size_t)K * sizeof *it);
    memset(zero, 0, (size_t)K * sizeof *zero);
    for (int i = 0; i < rj->o->threads; i++)
        for (int k = 1; k < K; k++) {
            const struct mlt_stats *s = &rj->stats[i];
            sum[k] += s->large[k].sum;
            sq[k] += s->large[k].sq;
            n[k] += s->large[k].n;
            it[k] += s->iters[k];
            zero[k] += s->zero_iters[k];
        }
    dist_sum_doubles(sum, (size_t)K);
    dist_sum_doubles(sq, (size_t)K);
    dist_sum_longs(n, (size_t)K);
    dist_sum_longs(it, (size_t)K);
    dist_sum_longs(zero, (size_t)K);
}

/* A missed length's chains start without light and splat nothing until they find some: their
 * iterations before that are a burn-in, discarded. The image divides each length's splats by
 * N P(k), the iterations it expects; this is the factor that divides them by the iterations
 * with light instead (1 for a length whose chains started from the pool: they never lose it). */
static double burn_in_factor(const struct run_job *rj, int k, long mutations, long it, long zero)
{
    if (zero == 0 || it == zero) return 1;
    return (double)mutations * (rj->kcdf[k] - rj->kcdf[k - 1]) / (double)(it - zero);
}

void normalisation_from_large_steps(const struct run_job *rj, struct mlt_result *r)
{
    double sum[MAX_PATH_LENGTH + 1], sq[MAX_PATH_LENGTH + 1];
    long n[MAX_PATH_LENGTH + 1], it[MAX_PATH_LENGTH + 1], zero[MAX_PATH_LENGTH + 1];
    large_sums(rj, sum, sq, n, it, zero);
    double ns = (double)rj->o->seed_paths, var_l = 0, var_p = 0, pooled = 0, b_new[MAX_PATH_LENGTH + 1];
    r->bl = 0;
    for (int k = 1; k <= rj->nk; k++) {
        double m = n[k] ? sum[k] / (double)n[k] : 0;
        double vm = n[k] > 1 ? fmax(0, sq[k] / (double)n[k] - m * m) / (double)(n[k] - 1) : 0;
        r->large_n[k] = n[k];
        r->bl_k[k] = m;
        r->bl_k_rse[k] = m > 0 ? sqrt(vm) / m : 0;
        r->bl += m;
        var_l += vm;
        /* the seed pass's variance of its mean, from its relative standard error */
        double vs = (r->b_k_rse[k] * r->b_k[k]) * (r->b_k_rse[k] * r->b_k[k]);
        double w = ns + (double)n[k];
        b_new[k] = (ns * r->b_k[k] + sum[k]) / w;
        pooled += b_new[k];
        var_p += (ns * ns * vs + (double)n[k] * (double)n[k] * vm) / (w * w);
    }
    r->bl_rse = r->bl > 0 ? sqrt(var_l) / r->bl : 0;
    r->b_image = r->b;
    r->b_image_rse = r->b_rse;
    if (!rj->o->progressive_norm) return;
    r->b_image = pooled;
    r->b_image_rse = pooled > 0 ? sqrt(var_p) / pooled : 0;
    /* each thread's length images into its image, each at its length's new b_k over the one its
     * chain splatted with, scale x P(k): the seed pass's, or a missed length's provisional one */
    for (int k = 1; k <= rj->nk; k++) {
        double b_old = rj->scale[k - 1] * (rj->kcdf[k] - rj->kcdf[k - 1]);
        double ratio = b_old > 0 ? b_new[k] / b_old * burn_in_factor(rj, k, r->mutations, it[k], zero[k]) : 0;
        for (int i = 0; i < rj->o->threads; i++)
            img_accumulate(rj->img[i], rj->len_img[i][k - 1], ratio);
    }
}
