/* One Markov chain's record for the mixing diagnostics (stats/mixing.h): exact counts of its
 * iterations and of the runs of iterations that left its state unchanged, and a thinned trace of
 * two scalars of its state, of fixed size.
 *
 * Thinning: the trace keeps the values of iterations 0, s, 2s, ... with s = 1 at first; when its
 * TRACE_CAP slots are full it keeps every other value and doubles s. So a chain of n iterations
 * holds between TRACE_CAP / 2 and TRACE_CAP values spread evenly over the whole chain, at O(1)
 * amortised cost per iteration (a countdown; a compaction of TRACE_CAP / 2 copies every time the
 * trace fills) and no allocation. The record is a flat struct: a checkpoint holds it as bytes and
 * the merge over MPI ranks moves it as bytes.
 *
 * Must never include anything of core/mcmc: the chains call it, not the other way round. */
#ifndef CHAIN_TRACE_H
#define CHAIN_TRACE_H

#include <stdbool.h>

/* Values kept per quantity; floats, as the diagnostics need ranks and a few digits, not the bits. */
#define TRACE_CAP 4096

struct chain_trace {
    int k;          /* the chain's path length (MMLT, PITP), 0 for PSSMLT's chains over all lengths */
    int len;        /* values held */
    long n;         /* iterations of this chain */
    long moved;     /* iterations that moved its path (core/mcmc/chain_loop.c says how that is seen) */
    long run;       /* the current run of unchanged iterations */
    long longest;   /* the longest such run */
    long stride;    /* values held are those of iterations 0, stride, 2 stride, ... */
    long countdown; /* iterations until the next value is kept */
    float contrib[TRACE_CAP], target[TRACE_CAP];
};

/* An empty record of a chain of path length k. */
void trace_init(struct chain_trace *t, int k);

/* Counts one iteration of the chain; true when its values are to be kept (then call trace_keep). */
static inline bool trace_step(struct chain_trace *t, bool moved)
{
    t->n++;
    if (moved) {
        t->moved++;
        t->run = 0;
    } else if (++t->run > t->longest) {
        t->longest = t->run;
    }
    return --t->countdown == 0;
}

/* Keeps the values of the iteration trace_step just counted. */
void trace_keep(struct chain_trace *t, double contrib, double target);

#endif
