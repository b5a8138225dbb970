/* Markov chain renderers in primary sample space, driving the same BDPT code as the Monte Carlo
 * renderer (thesis §3.5-3.8; MMLT paper §3-4).
 *
 * PSSMLT: the state is one pair of subpaths; its target is the luminance of the MIS-weighted sum of
 * all their connections (as the thesis's Chapter 6 uses it).
 * MMLT: one chain per path length k (per thread); the state adds a technique number
 * (STREAM_TECHNIQUE) choosing t = 1 + floor((k + 1) u) camera vertices and s = k + 1 - t emitter
 * vertices; the target is (k + 1) w_t C_t (MMLT Eq. 20; k + 1 techniques because a pinhole cannot
 * be hit, so t = 0 is not a technique here). Each iteration picks k with probability b_k / sum b.
 *
 * Normalisation: a seed pass of `seed_paths` independent samples (per length for MMLT) estimates
 * b; each chain starts from a seed sample resampled in proportion to its target, so there is no
 * start-up bias. Splatting uses expected values: weight a on the proposal and 1 - a on the current
 * state. Each run is reproducible from its seed and thread count (with a mutation budget).
 * Over MPI ranks (base/dist.h) the seed pass, the chains' streams and the mutation budgets belong
 * to the job's global threads, so N ranks of T threads give one process of N * T threads' image and
 * statistics. The image and statistics are the job's on rank 0 only (elsewhere partial sums); the
 * counts (mutations, controlled-step failures) and the normalisation are the job's on every rank.
 *
 * The implementation, by concern: driver.c (mlt_render: checks, threads, merge, resume),
 * seed_pass.c (seed pass, normalisation, chain start), chain_loop.c (the iterations), splat_ev.c
 * (expected-value splats), pssmlt.c and mmlt.c (the two methods' state evaluation), mctls.c
 * (MCTLS), pitp.c (PITP), controlled_step.c (controlled small steps), tech_split.c (technique
 * images), chain.h and chain_checkpoint.c (a thread's state and its checkpoint). */
#ifndef MLT_H
#define MLT_H

#include "io/checkpoint.h"
#include "io/image.h"
#include "mcmc/controlled_step.h"
#include "sampler/pss.h"
#include "scene/scene.h"
#include "stats/angle_change.h"
#include "stats/chain_trace.h"
#include "stats/mlt_stats.h"
#include "stats/pixel_mixing.h"
#include "stats/tech_image.h"

/* MLT_PITP: MMLT with the path-invariant technique perturbation before every small step (thesis
 * §5.2, mcmc/pitp.h); every MMLT option applies. MLT_VEACH: Veach's MLT, a path-space state and
 * its mutations (mcmc/veach.h, docs/veach.md), one chain per thread with PSSMLT's seed pass. */
enum mlt_method { MLT_PSSMLT, MLT_MMLT, MLT_PITP, MLT_VEACH };
/* One chain per path length (MMLT and PITP), or one over all lengths. */
static inline bool mlt_multiplexed(enum mlt_method m) { return m == MLT_MMLT || m == MLT_PITP; }

/* MMLT's large step: fresh numbers (MMLT), the multiple correlated-try large step of thesis §4.3
 * (Eq. 4.2-4.7: trace both subpaths to length k, pick one of the k + 1 connections in proportion to
 * its target, accept with min(1, sum_i pi(y_i) / sum_i pi(x_i))), or MMLT below hybrid_length and
 * MCTLS from it on. */
enum large_step { LARGE_MMLT, LARGE_MCTLS, LARGE_HYBRID };

/* The fused perturbations a multiplexed chain makes (mcmc/fused.c), a set of Veach's perturbations:
 * each fused step makes one of those in it, with equal probabilities. */
enum fused_moves { FUSED_NONE = 0, FUSED_LENS = 1, FUSED_CAUSTIC = 2, FUSED_MULTICHAIN = 4, FUSED_ALL = 7 };

struct mlt_opts {
    enum mlt_method method;
    struct pss_opts pss;
    double p_large;
    long mutations; /* total over all threads; ignored when seconds > 0 */
    double seconds; /* equal-time budget */
    bool cpu_time;  /* seconds are CPU seconds per thread (budget_seconds, parallel.h) */
    long seed_paths;
    /* MMLT/PITP: b_k from BDPT samples, one per seed path and length (all k + 1 techniques, the MMLT
     * paper's §4 "Initialization"), instead of from the seed pool's one-technique targets; the pool
     * still starts the chains. Both are unbiased (seed_pass.c). */
    bool seed_bdpt;
    uint64_t seed;
    int threads;
    int max_length;
    int min_length; /* paths shorter than this (segments) are left out */
    bool progress;
    enum large_step large_step; /* MMLT only */
    int hybrid_length;
    /* MCTLS's trials, for analysis (fig4.5): 0 = every technique once (Eq. 4.7, the limit of many
     * trials); N > 0 = Eq. 4.5 with N trials whose techniques are drawn uniformly with replacement,
     * the denominator the current state's own technique and N - 1 drawn ones (MCTM with N
     * correlated tries; N = 1 is an MMLT large step). mctls_count_t0 (only with N > 0) draws them
     * among k + 2 techniques, as the thesis counts them: t = 0, a hit on the pinhole camera, is a try
     * with no contribution. Both recompute the current state's trials at every step: their timings
     * and connection counts are not those of Eq. 4.7's. */
    int mctls_tries;
    bool mctls_count_t0;
    /* MCTLS (Eq. 4.7) re-evaluates the current state's trials at every step instead of keeping them
     * from when it was proposed: the same chain, at the cost the thesis's ray count assumes
     * (§4.3.1: 2k + 2 rays more per step), for fig4.6's test of that count. */
    bool mctls_recompute;
    bool uniform_lengths; /* MMLT: every length gets the same share of mutations, not b_k */
    /* MMLT paper §4: b_k re-estimated at the end from the seed pass and every large step's fresh
     * numbers together (progressive_norm.c); the image's length-k part is rescaled to it exactly */
    bool progressive_norm;
    /* MMLT paper §4's alternative: one chain per thread over all lengths, the length changed by the
     * large steps only (one_chain.c), instead of one chain per length */
    bool one_chain;
    bool time_proposals; /* record each proposal's time in the statistics (two clock reads) */
    bool max_heuristic;  /* PSSMLT: Kelemen's maximum heuristic instead of the balance heuristic */
    /* PSSMLT: Kelemen et al.'s combination of the large steps, independent samples of the uniform
     * density, with the chain's expected values (splat_ev.h), as Tungsten's kelemen_mlt does */
    bool large_step_mis;
    bool power_heuristic; /* MMLT: the power heuristic (beta = 2) in the target (MMLT paper §6) */
    /* MMLT's small step: the lazy primary-sample-space step, or thesis §5.3's controlled step
     * (Alg. 4) or root perturbation (Alg. 3), see controlled_step.h. Controlled and root need the
     * Gaussian kernel without --cdc, and MMLT large steps. */
    enum small_step small_step;
    /* PITP: the probability that a small step is preceded by the technique perturbation (1: the
     * thesis's, every small step; 0: MMLT's small steps). Below 1 the decision is drawn from the
     * worker's generator (pitp_step.c); at 0 and 1 nothing is drawn. A zero-initialised struct
     * has 0: initialisers that run PITP set it (mlt_opts_defaults gives 1). */
    double pitp_rate;
    bool angle_stats; /* MMLT: angle change of every small step (angle_change.h) */
    /* the per-pixel mixing counters (stats/pixel_mixing.h; render's PREFIX.mixing.exr): opt-in, as
     * their count per iteration (+1.4 % of a Cornell-box MMLT mutation) would take the diagnostics
     * past their 2 % budget */
    bool mixing_image;
    bool ctrl_unit_ratio; /* tests only: T(v->u) / T(u->v) replaced by 1 (a broken chain) */
    bool veach_broken_t;  /* tests only: T(x -> y) of a bidirectional mutation that lengthens x, x1.1 */
    /* Veach's MLT: the probability that an iteration is a lens perturbation (else a bidirectional
     * mutation); 0 in a zero-initialised struct (mlt_opts_defaults gives 0.4) */
    double veach_lens;
    double veach_caustic;      /* the same for the caustic perturbation (mlt_opts_defaults: 0.2) */
    double veach_lens_subpath; /* ... for the lens subpath mutation (mlt_opts_defaults: 0.1) */
    double veach_multichain;   /* ... and for the multi-chain perturbation (mlt_opts_defaults: 0.1) */
    /* Fused perturbations (Otsu et al. 2017; mcmc/fused.c, docs/fused.md): on mmlt and pitp, a share
     * fused_rate of the small steps is a path-space perturbation of the chain's path mapped back
     * into primary sample space by the inverse of the chain's technique. FUSED_NONE in a
     * zero-initialised struct; mlt_opts_defaults gives fused_rate 0.5 */
    enum fused_moves fused;
    double fused_rate;
    bool lens_broken_t; /* tests only: T(x -> y) of a lens perturbation (Veach's or fused) toward larger raster x, x1.1
                         */
    /* Checkpoints (checkpoint.h): periodic, at an interruption, and resuming. With a mutation
     * budget a resumed run ends bit-identical to an uninterrupted one; with a time budget it runs
     * for what the checkpointed run had left. The seed pass is not checkpointed (a checkpoint
     * holds the normalisation it found). */
    struct ckpt_ctl *ckpt;
    int technique_k; /* > 0: per-technique images of this path length (pssmlt, mmlt; tech_image.h) */
};

struct mlt_result {
    struct image *img; /* final units, like render_mc */
    struct mlt_stats stats;
    double b; /* total normalisation sum_k b_k */
    double b_k[MAX_PATH_LENGTH + 1];
    /* The seed pass's relative standard errors: of b and of each b_k (sd / (mean sqrt n) over the
     * seed paths; 0 where b_k is 0). They move every MCMC image's mean, and a length's share. */
    double b_rse, b_k_rse[MAX_PATH_LENGTH + 1];
    /* The large steps' own estimate of the same (every large step of fresh numbers is an independent
     * sample of its length's b_k): its samples, value and relative standard error; b_image, the
     * estimate the image is scaled to: the seed pass's, or under progressive_norm both pooled. */
    long large_n[MAX_PATH_LENGTH + 1];
    double bl, bl_rse, bl_k[MAX_PATH_LENGTH + 1], bl_k_rse[MAX_PATH_LENGTH + 1];
    double b_image, b_image_rse;
    long mutations;
    double seconds, seed_seconds;
    long nonfinite;          /* contributions dropped as NaN or infinite; by length in stats.nonfinite */
    bool partial;            /* interrupted: fewer mutations than asked (the image stays unbiased) */
    struct angle_acc *angle; /* with angle_stats */
    long ctrl_fail_forward, ctrl_fail_reverse; /* controlled steps: impossible inversions */
    struct tech_acc *tech;                     /* with technique_k */
    /* Every chain's mixing record (stats/chain_trace.h; stats/mixing.h turns them into the
     * diagnostics), the job's global threads in order, each thread's chains by length: over MPI
     * ranks too, on rank 0. */
    struct chain_trace *trace;
    int ntrace;
    struct pixel_mixing
        *mix; /* with mixing_image: visits over splats per pixel (stats/pixel_mixing.h), rank 0; else NULL */
};

/* Returns false (with a message) when the seed pass finds no light at all. */
bool mlt_render(const struct scene *sc, const struct mlt_opts *o, struct mlt_result *r, char *err, size_t errlen);
void mlt_result_free(struct mlt_result *r);

#endif
