/* Distribution of one render over processes (MPI ranks; README "MPI: paper-scale runs").
 *
 * The default build has one process (core/base/dist_single.c); `make MPI=1` links core/base/dist_mpi.c, where
 * a program started by mpirun has dist_size() ranks. Work is dealt over the global thread index
 * g = rank * T + tid of N * T threads, so that N ranks of T threads take exactly the samples, chains
 * and random streams of one process of N * T threads, and dist_chain adds the per-thread results in
 * the same order as that process does: the images are the same bits.
 *
 * Only the calling thread of a rank talks to the others, one call at a time (MPI_THREAD_SERIALIZED:
 * a time-budgeted render decides its next pass on whichever worker thread arrives last). */
#ifndef DIST_H
#define DIST_H

#include <stdbool.h>
#include <stddef.h>

/* Joins the job (MPI: when a launcher started the process; otherwise a job of one). Ranks other
 * than 0 then write nothing: their stdout and stderr go to /dev/null, so that an error every rank
 * finds (bad option, missing scene) is printed once, by rank 0. Finalisation is registered with
 * atexit, so every exit path leaves the job cleanly. */
void dist_init(int *argc, char ***argv);
void dist_finalize(void);
/* Rank and size of the job: 0 and 1 in a program that did not call dist_init. A program built with
 * MPI=1 that did not call dist_init but was started by mpirun with several processes is not
 * rank-aware: the first of these calls prints one line (on the launcher's rank 0) and exits 2. */
int dist_rank(void);
int dist_size(void);
/* The same refusal, at once: for tools that do not render in-process but would misbehave as
 * several copies (bin/ch6_equal starts bin/render processes, which would take its launcher's
 * variables for their own). */
void dist_refuse_ranks(void);
static inline bool dist_root(void) { return dist_rank() == 0; }

/* Sums over ranks, in place, identical on every rank. Each entry must come from one rank (the others
 * give 0) or be an integer, so that the sum is exact and independent of the reduction order. */
void dist_sum_doubles(double *v, size_t n);
void dist_sum_longs(long *v, size_t n);
/* Rank 0's value, on every rank. */
bool dist_bcast_bool(bool v);
/* The largest of the ranks' values, on every rank. */
double dist_max_double(double v);

/* An ordered reduction that reproduces a one-process sum over threads: the buffers travel from rank
 * 0 to rank 1, ..., to the last rank and back to rank 0; each rank, on receiving the partial, calls
 * add(ctx) to add its own threads in their order. Rank 0's buffers must hold the starting value (as
 * a one-process run starts from zero) and end with the result; the other ranks' buffers are scratch
 * of the same sizes. */
struct dist_buf {
    void *p;
    size_t bytes;
};
void dist_chain(const struct dist_buf *bufs, int nbufs, void (*add)(void *ctx), void *ctx);

/* The first global thread of this rank, with T threads per rank. */
static inline int dist_thread0(int threads) { return dist_rank() * threads; }

#endif
