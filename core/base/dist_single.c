/* The one-process job of the default build (core/base/dist.h): every collective is the identity, and the
 * ordered chain is this process's own sum over its threads. */
#include "base/dist.h"
#include <stdlib.h>

void dist_init(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
}

void dist_finalize(void) {}

/* Without MPI there is no launcher to recognise: copies started by one run independently. */
void dist_refuse_ranks(void) {}

int dist_rank(void) { return 0; }
int dist_size(void) { return 1; }

void dist_sum_doubles(double *v, size_t n)
{
    (void)v;
    (void)n;
}

void dist_sum_longs(long *v, size_t n)
{
    (void)v;
    (void)n;
}

bool dist_bcast_bool(bool v) { return v; }
double dist_max_double(double v) { return v; }

void dist_chain(const struct dist_buf *bufs, int nbufs, void (*add)(void *ctx), void *ctx)
{
    (void)bufs;
    (void)nbufs;
    add(ctx);
}
