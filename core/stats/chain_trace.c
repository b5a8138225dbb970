/* A chain's thinned trace (see chain_trace.h). */
#include "stats/chain_trace.h"
#include <string.h>

void trace_init(struct chain_trace *t, int k)
{
    memset(t, 0, sizeof *t);
    t->k = k;
    t->stride = 1;
    t->countdown = 1;
}

void trace_keep(struct chain_trace *t, double contrib, double target)
{
    t->contrib[t->len] = (float)contrib;
    t->target[t->len] = (float)target;
    t->len++;
    /* the next kept iteration is `stride` on, also right after a compaction: the values held then
     * are those of multiples of 2 stride, and the next multiple is this iteration + stride */
    t->countdown = t->stride;
    if (t->len < TRACE_CAP) return;
    for (int i = 0; i < TRACE_CAP / 2; i++) {
        t->contrib[i] = t->contrib[2 * i];
        t->target[i] = t->target[2 * i];
    }
    t->len = TRACE_CAP / 2;
    t->stride *= 2;
}
