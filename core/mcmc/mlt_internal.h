/* What the MLT driver's files share (driver.c, seed_pass.c, chain_loop.c): the run's job, a worker
 * thread's context, and the method's state evaluation. Not part of the API (mlt.h).
 *
 * A run (MMLT paper §4, Alg. 1-2; thesis §3.7-3.8): the seed pass estimates the normalisation b_k
 * and keeps its targets as a pool (seed_pass.c); each worker thread starts its chains by
 * resampling that pool and runs its share of the iterations (chain_loop.c); the driver merges the
 * threads' images and statistics (driver.c). */
#ifndef MLT_INTERNAL_H
#define MLT_INTERNAL_H

#include "base/parallel.h"
#include "mc/integrator.h"
#include "mcmc/chain.h"
#include "mcmc/controlled_step.h"
#include "mcmc/mctls.h"
#include "mcmc/mlt.h"
#include "mcmc/mmlt.h"
#include "mcmc/pitp.h"
#include "mcmc/pssmlt.h"
#include <stdatomic.h>

/* The run, shared by its threads. */
struct run_job {
    const struct scene *sc;
    const struct mlt_opts *o;
    int nk;                                 /* lengths with a seed pool: 1 (PSSMLT) or K (MMLT) */
    int nch;                                /* chains per thread: nk, or 1 (one_chain) */
    const double *cdf[MAX_PATH_LENGTH + 1]; /* per chain index: seed-pool CDF over i (NULL: no light) */
    double kcdf[MAX_PATH_LENGTH + 2];       /* length selection */
    double scale[MAX_PATH_LENGTH + 1];      /* per chain index: b_k / P(k) */
    struct image **img;
    struct image ***len_img; /* progressive_norm: per thread, one image per chain index (else NULL) */
    struct mlt_stats *stats;
    struct angle_acc *angle; /* per thread, with angle_stats */
    struct tech_acc *tech;   /* per thread, with technique_k */
    long (*ctrl_fail)[2];    /* per thread: forward, reverse */
    long *done;
    struct chain_trace **trace; /* per thread, nk each: the chains' mixing records */
    struct pixel_mixing *mix;   /* per thread: the per-pixel mixing counters */
    int g0, stride;             /* this rank's first global thread; the job's threads (base/dist.h) */
    double t0;
    struct progress prog;
    /* checkpoints (o->ckpt): the rendezvous, the run's normalisation, and on resume each thread's
     * saved state */
    struct ckpt_sync sync;
    const struct mlt_result *res;
    struct ckpt_buf *resume;
    atomic_bool resume_bad;
    double elapsed0; /* chain seconds before the resume */
};

/* One worker thread: its chains, generator and counts (saved: what a checkpoint holds of them), its
 * shares of the job's accumulators, and the scratch its proposals are traced into. */
struct worker {
    struct run_job *job;
    const struct mlt_opts *opts;
    int tid, global_tid;      /* the thread, and the job's global thread (streams, budgets) */
    struct path_ctx path_ctx; /* the scene and path lengths the walks and connections use */
    struct chain *ch;         /* job->nk chains */
    rng r;                    /* length selection, step kind, acceptance */
    long n;                   /* iterations done */
    struct mlt_stats *st;
    struct image *img;
    struct tech_acc *tech;   /* or NULL */
    struct angle_acc *angle; /* or NULL */
    long *ctrl_fail;         /* [2]: forward, reverse */
    struct pixel_mixing *mix;
    bool pitp, multiplexed;
    bool keep_path;  /* chains keep their path in its technique's form (chain.x): PITP, --fused */
    bool track;      /* chains keep their subpaths (controlled steps, angle statistics) */
    int tech_before; /* the current chain's technique when the iteration began */
    struct mlt_thread saved;
    /* scratch */
    struct scratch *scratch; /* walks and connections of the proposal being traced */
    struct splat_list prop;  /* the proposal's splats */
    struct mmlt_path *spare; /* the proposal's path; under PITP swapped with the chain's on accept */
    struct mctls_buf *mctls_buf;
    struct pitp_scratch *pitp_scratch; /* PITP only */
    struct ctrl_sampler *ctrl;         /* controlled and root small steps only */
    struct veach_scratch *veach;       /* Veach's MLT and --fused only (veach.h) */
};

/* The chain index of a length drawn with P(k) (the job's kcdf) by u in [0, 1). */
static inline int length_index(const struct run_job *j, double u)
{
    int kk = 0;
    u *= j->kcdf[j->nk];
    while (kk < j->nk - 1 && j->kcdf[kk + 1] <= u)
        kk++;
    return kk;
}

/* The seed pass's stream of sample i for chain index kk: the chain start reproduces the sample. */
static inline uint64_t seed_stream(long i, int nk, int kk) { return (uint64_t)i * (uint64_t)nk + (uint64_t)kk; }

/* The method's state read from sampler s (pssmlt.h, mmlt.h): its splats into out and its scalar
 * target (0 for no contribution). For MMLT and PITP, *tech receives the camera vertex count t and x
 * the path in t's form; *complete whether both subpaths reached their vertex counts. */
static inline double eval_state(enum mlt_method m, const struct path_ctx *pc, struct sampler *s, struct scratch *w,
                                int k, struct mmlt_path *x, struct splat_list *out, int *tech, bool *complete)
{
    if (!mlt_multiplexed(m)) { /* PSSMLT's, and Veach's MLT's seed pass and start */
        *tech = 0;
        *complete = false;
        return pssmlt_eval_state(pc, s, w, out);
    }
    double f = mmlt_eval_state(pc, s, k, x, out, &w->nf);
    if (x->complete) { /* one connection, evaluated when both subpaths reached their vertices */
        w->conn_tried++;
        w->conn_nonzero += f > 0;
    }
    *tech = x->t;
    *complete = x->complete;
    return f;
}

/* seed_pass.c: the seed pass and the normalisation (b_k, the length selection, the seed pools);
 * false (with a message) when it finds no light. */
bool normalise(struct run_job *rj, struct mlt_result *r, char *err, size_t errlen);
/* seed_pass.c: starts chain c (index kk) of the worker from a seed sample resampled in proportion
 * to its target. */
void chain_start(struct worker *wk, struct chain *c, int kk);

/* progressive_norm.c: the large steps' estimate of b_k into r (bl_k, b_image, ...) and, under
 * progressive_norm, each thread's length images rescaled to the pooled b_k into its image. */
void normalisation_from_large_steps(const struct run_job *rj, struct mlt_result *r);
/* one_chain.c (mlt_opts.one_chain): the chain's first length, drawn in proportion to the seed
 * pools' sums; and a large step's new length, drawn with P(k), into pr (k, and T's ratio in tr). */
int one_chain_first(struct worker *wk);
struct proposal;
void one_chain_length(struct worker *wk, struct proposal *pr);
/* chain_loop.c: one worker thread's run (parallel_run's function; p is the run_job). */
void run_worker(int tid, void *p);

#endif
