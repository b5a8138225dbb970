/* The per-thread results of a render merged over every thread of the job, in global thread order
 * (rank 0's threads, then rank 1's, ...), through core/dist.h's ordered chain: the same additions, in
 * the same order, as one process running all the job's threads, hence the same bits. In a job of
 * one this is the plain loop over the threads. */
#ifndef DIST_MERGE_H
#define DIST_MERGE_H

#include "io/image.h"
#include "stats/angle_change.h"
#include "stats/mlt_stats.h"

struct thread_results {
    int threads;               /* this rank's */
    struct image **img;        /* per thread, each added with weight `scale` */
    double scale;
    struct mlt_stats *stats;   /* per thread, or NULL */
    struct angle_acc *angle;   /* per thread, or NULL */
};

/* Adds every thread's results into img_out, stats_out and angle_out (the latter two when the
 * threads have them), which start as the job's zero. Only on rank 0 do they end as the job's
 * totals; other ranks' are partial sums, for nobody to read. */
void merge_thread_results(const struct thread_results *t, struct image *img_out, struct mlt_stats *stats_out,
                          struct angle_acc *angle_out);

#endif
