/* The six MCMC algorithms of the CMLT paper's §5 on the two-light toy (cmlt_scene.h), with the
 * two charts of cmlt_charts.h:
 *   PSS-MLT-1, PSS-MLT-2  one chain in U_1 (resp. U_2), target pi_i(u) = f*(T_i u)/p_i(T_i u), Eq. 13;
 *   PSS-MLT-AVG           two chains, one per chart, each with the Eq. 13 target; every sample of
 *                         chain i is weighted by the balance heuristic w_i = p_i/(p_1 + p_2);
 *   PSS-MLT-MIX           two chains, one per chart, target pi_i(u) = f* / (p_1 + p_2), Eq. 15/17;
 *   CMLT-EPSM             one chain in path space, target f*, whose steps alternate ephemeral
 *                         primary-space perturbations through chart 1 and chart 2: u = R_i(x),
 *                         u' = K(u), y = T_i(u'), accepted with Eq. 27/28;
 *   CMLT                  the MIX pair of chains (targets Eq. 21) plus a replica-exchange chart swap
 *                         every `swap_every` iterations: chain 1 gets R_1(x_2), chain 2 gets R_2(x_1),
 *                         accepted with Eq. 25 (no target evaluation).
 * The primary-space kernel K is a mixture: with probability p_large an independent uniform point of
 * [0,1)^4 (Kelemen's large step), otherwise Kelemen's exponential small step per dimension with
 * wrap-around (magnitudes s2 exp(-ln(s2/s1) xi), xi quantised to 4096 levels, random sign); both are
 * symmetric, K(u'|u) = K(u|u'), as Eq. 13/15/28 assume.
 * Budget: n chain steps in total; two-chain algorithms run n/2 steps per chain (as in the paper).
 * Normalisation b_i = integral of each chain's target and the start states come from a seed pass
 * of n_seed independent samples of each chart, combined with the balance heuristic; the start state
 * of each chain is resampled from the seed samples in proportion to target/proposal density (no
 * start-up bias in the limit). The image estimate uses expected-value splatting. */
#ifndef CMLT_MCMC_H
#define CMLT_MCMC_H

#include <signal.h>
#include <stdint.h>

struct progress; /* base/parallel.h */

enum cmlt_algo { CMLT_PSS1, CMLT_PSS2, CMLT_PSS_AVG, CMLT_PSS_MIX, CMLT_EPSM, CMLT_CMLT, CMLT_NALGO };
extern const char *const cmlt_algo_names[CMLT_NALGO];

struct cmlt_config {
    int w, h;        /* image resolution */
    uint64_t n;      /* total chain steps (= samples), split evenly over the chains */
    uint64_t n_seed; /* seed-pass samples per chart */
    double p_large;  /* probability of a large step */
    double s1, s2;   /* Kelemen small-step range */
    int swap_every;  /* CMLT: a chart swap after every this many iterations (paper: 4) */
};

struct cmlt_stats {
    uint64_t steps;      /* chain steps done (all chains) */
    double acc_sum;      /* sum of acceptance probabilities of the steps */
    uint64_t accepted;   /* accepted steps */
    uint64_t swaps;      /* CMLT: swap attempts */
    double swap_acc_sum; /* CMLT: sum of swap acceptance probabilities */
    uint64_t swaps_accepted;
    double b[3];    /* normalisations: integral of f*, of w_1 f*, of w_2 f* */
    double seconds; /* wall time of the run (seed pass + chains) */
    int partial;    /* stopped early */
};

void cmlt_config_default(struct cmlt_config *c);

/* Runs algorithm `a` with a generator seeded by (seed, stream); writes the image estimate (3
 * doubles per pixel, row 0 on top, pixel value = radiance averaged over the pixel) into img, which
 * must hold w*h*3 doubles. Allocates only at start. `progress` (may be NULL) counts chain steps as
 * they are done; a non-zero *stop (may be NULL) ends the chains early (stats->partial = 1). */
void cmlt_run(enum cmlt_algo a, const struct cmlt_config *c, uint64_t seed, uint64_t stream, double *img,
              struct cmlt_stats *stats, struct progress *progress, const volatile sig_atomic_t *stop);

/* Replica-exchange chart swap ratio (Eq. 22 with Eq. 24, i.e. Eq. 25 written with path densities,
 * r_i = 1/p_i): chain i holds x1, chain j holds x2; the swap gives chain i the path x2 and chain j
 * the path x1. Returns p_i(x2) p_j(x1) / (p_i(x1) p_j(x2)); accept with min(1, ratio). */
double cmlt_swap_ratio(double pi_x1, double pj_x1, double pi_x2, double pj_x2);
/* Ephemeral primary-space perturbation through chart i with a symmetric kernel, Eq. 28: target
 * pi (path space), current x, proposal y. Returns pi(y) p_i(x) / (pi(x) p_i(y)). */
double cmlt_epsm_ratio(double pi_x, double pi_y, double p_i_x, double p_i_y);

#endif
