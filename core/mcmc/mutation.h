/* A mutation of the MLT chains: a registered set of operations (mutation_registry.c). Each
 * iteration (chain_loop.c) picks a chain and draws the step kind (large with probability p_large);
 * then the registry is walked in order: every mutation whose `applies` is true runs its `step`, and
 * the first one that is not `before` another ends the iteration. The built-in ones, in order:
 * MCTLS's large step (mctls.c), PITP's technique perturbation before a small step (pitp_step.c),
 * the large step of fresh numbers and the small step (primary-sample-space, controlled or root;
 * pss_step.c); under --method mlt, Veach's path-space mutations (veach.c) before all of them,
 * ending every iteration; under --fused, the fused perturbations (fused.c) before the small step,
 * which makes the small steps it does not replace. Mutations registered at run time (mutation_register) come before
 * them.
 *
 * Adding one: its file, which defines a `const struct mutation` (tests/mcmc/toy_mutation.c is a
 * whole example), and one line in mutation_registry.c's table (or one mutation_register call). Its
 * statistics rows (stats/mlt_stats.h) are named after it; its per-chain state, if any, is
 * allocated, checkpointed (as raw bytes unless it has save and load) and freed by the registry. */
#ifndef MUTATION_H
#define MUTATION_H

#include "mcmc/mlt_internal.h"

/* A proposal evaluated: its target (0 after an impossible inversion), the kernel's ratio
 * T(v->u) / T(u->v), its path length (the chain's, but for --one-chain's large steps), its
 * technique, whether its subpaths are complete, and whether it was refused before it was made (its
 * statistics row's `failed`). */
struct proposal {
    double f, tr;
    int k, tech;
    bool complete, failed;
};

struct mutation {
    const char *name; /* its statistics rows' kind */
    bool before;      /* runs before the iteration's step (and does not end the iteration) */
    /* whether it acts in this iteration (large: the step kind drawn); draws no random numbers */
    bool (*applies)(const struct worker *wk, const struct chain *c, bool large);
    /* the step itself: its proposal, acceptance, splats and statistics; t_start for the timings */
    void (*step)(struct worker *wk, struct chain *c, bool large, double t_start);
    size_t chain_state; /* bytes of per-chain state (0: none), zeroed when the chain starts */
    /* whether a run of these options uses it (NULL: every run); a chain of a run that does not
     * gets no state of it (NULL), and its save and load see that NULL */
    bool (*wanted)(const struct mlt_opts *o);
    /* its per-chain state in a checkpoint when not flat bytes (state: the registry's, or NULL);
     * load is false when the bytes do not fit */
    void (*save)(struct ckpt_buf *b, const struct scene *sc, const struct chain *c, const void *state);
    bool (*load)(struct ckpt_buf *b, const struct scene *sc, struct chain *c, void *state);
};

/* The built-in mutations (their files'). */
extern const struct mutation mutation_veach, mutation_mctls, mutation_pitp, mutation_fused, mutation_large,
    mutation_small;

/* Adds m before the built-in mutations (before the first mlt_render of the process). Returns its
 * statistics kind (stats/mlt_stats.h), or -1 when the registry or the statistics are full. */
int mutation_register(const struct mutation *m);
/* One iteration's steps for chain c (chain_loop.c). */
void mutations_iterate(struct worker *wk, struct chain *c, bool large, double t_start);
/* The chains' per-mutation state: allocated, freed, and in and out of checkpoints (chain_checkpoint.c). */
void mutations_chain_alloc(struct chain *c, const struct mlt_opts *o);
void mutations_chain_free(struct chain *c);
void mutations_chain_save(struct ckpt_buf *b, const struct scene *sc, const struct chain *c);
bool mutations_chain_load(struct ckpt_buf *b, const struct scene *sc, struct chain *c);
/* A mutation's per-chain state in c (NULL when it has none). */
void *mutation_state(const struct chain *c, const struct mutation *m);

/* What the steps share (pss_step.c). */
/* A proposal of fresh numbers (large) or a small step, traced into the worker's scratch. */
void mutation_propose(struct worker *wk, struct chain *c, bool large, struct proposal *pr);
/* Its acceptance (MMLT paper Eq. 17-20), expected-value splats and statistics row of kind `kind`. */
void mutation_decide(struct worker *wk, struct chain *c, int kind, const struct proposal *pr, double t_start);
/* The connections the last evaluations counted in the scratch, into the thread's statistics. */
void mutation_take_connections(struct worker *wk);
/* The seconds since t_start when the proposals are timed, else 0. */
double mutation_elapsed(const struct worker *wk, double t_start);

#endif
