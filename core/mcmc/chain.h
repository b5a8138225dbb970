/* A Markov chain's state (one per path length and thread for MMLT, one per thread for PSSMLT), and
 * everything a worker thread carries from one iteration to the next (chain_loop.c), with their
 * checkpoint I/O (chain_checkpoint.c): what a resumed run must restore to continue bit-identically. */
#ifndef CHAIN_H
#define CHAIN_H

#include "io/checkpoint.h"
#include "mcmc/controlled_step.h"
#include "mcmc/mmlt.h"
#include "path/splat.h"
#include "sampler/pss.h"
#include "stats/angle_change.h"
#include "stats/chain_trace.h"
#include "stats/mlt_stats.h"
#include "stats/tech_image.h"

/* Per-chain state slots of the mutations (mcmc/mutation.h): those registered at run time, and room
 * for the built-in table. */
#define MUTATIONS_ADDED_MAX 4
#define MUTATIONS_MAX (MUTATIONS_ADDED_MAX + 12)

struct chain {
    struct pss_sampler pss;
    struct splat_list cur;
    double f;
    int k, tech;
    double scale;      /* b_k / P(k): the chain's splat weight */
    struct image *img; /* where its splats go: the thread's image, or its length's (progressive_norm) */
    double xsum;       /* MCTLS: sum over techniques of the current numbers' targets */
    double mis_pl;     /* --large-step-mis: p_large, the large steps' density in every weight; else 0 */
    double pending;    /* expected-value weight (sum of 1 - a) owed to `cur`, splatted when it changes */
    bool xsum_valid;
    struct ctrl_path *path;     /* controlled steps and angle statistics: the current subpaths */
    struct mmlt_path *x;        /* PITP: the current path in its technique's form (swapped with a spare on accept) */
    long *dropped;              /* where its weighted splats that come out non-finite are counted (a
                                 * tiny target's weight can overflow): its length's cell, PSSMLT's [0] */
    void *state[MUTATIONS_MAX]; /* each mutation's own, by its place in the registry (or NULL) */
    struct chain_trace *trace;  /* its mixing record (the job's, stats/chain_trace.h) */
};

/* Everything one worker thread carries from one iteration to the next. Scratch buffers (walks,
 * the proposal's splats and path) are rewritten by every proposal before they are read, so they
 * are not part of it. */
struct mlt_thread {
    struct chain *ch; /* nk chains; path and x allocated as the run needs them */
    int nk;
    rng *r;  /* length selection, step kind, acceptance */
    long *n; /* iterations done */
    struct nonfinite *nonfinite;
    struct mlt_stats *st;
    long *ctrl_fail; /* [2]: forward, reverse */
    struct image *img;
    struct image **len_img;    /* nk, or NULL (progressive_norm) */
    struct angle_acc *angle;   /* or NULL */
    struct tech_acc *tech;     /* or NULL */
    struct chain_trace *trace; /* nk: the chains' mixing records */
};

/* Replaces b's contents with the thread's state. */
void mlt_thread_save(struct ckpt_buf *b, const struct scene *sc, const struct mlt_thread *t);
/* False when the bytes do not fit this run's layout. */
bool mlt_thread_load(struct ckpt_buf *b, const struct scene *sc, const struct mlt_thread *t);

#endif
