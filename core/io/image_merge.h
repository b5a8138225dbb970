/* The per-thread results of a render merged over every thread of the job, in global thread order
 * (rank 0's threads, then rank 1's, ...), through base/dist.h's ordered chain: the same additions,
 * in the same order, as one process running all the job's threads, hence the same bits. In a job of
 * one this is the plain loop over the threads. */
#ifndef IMAGE_MERGE_H
#define IMAGE_MERGE_H

#include "base/dist.h"
#include "io/image.h"

#define MERGE_MAX_EXTRA 7

struct thread_results {
    int threads;        /* this rank's */
    struct image **img; /* per thread, each added with weight `scale` */
    double scale;
    /* Further per-thread results (statistics) merged in the same pass: after thread i's image,
     * add(ctx, i) adds its results into the outputs, whose bytes `extra` lists so that they
     * travel between ranks. */
    struct dist_buf extra[MERGE_MAX_EXTRA];
    int nextra;
    void (*add)(void *ctx, int thread);
    void *ctx;
};

/* Adds every thread's results into img_out (and the extra outputs), which start as the job's zero.
 * Only on rank 0 do they end as the job's totals; other ranks' are partial sums, for nobody to read. */
void merge_thread_results(const struct thread_results *t, struct image *img_out);

#endif
