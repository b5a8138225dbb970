/* Worker threads and a progress bar on stderr. Core code never prints elsewhere. */
#ifndef PARALLEL_H
#define PARALLEL_H

#include <pthread.h>
#include <stdatomic.h>
#include <stdbool.h>

/* Runs fn(tid, ctx) on `threads` threads (tid 0 on the caller's thread) and joins them. */
void parallel_run(int threads, void (*fn)(int tid, void *ctx), void *ctx);

/* Where the threads of a run made of passes meet after each pass. The last to arrive calls
 * decide(ctx), alone, which sets up the next pass and returns true, or returns false to end the
 * run; every thread gets that answer. Threads that work in passes stay alive across them: starting
 * new ones for every pass cost PT on a 64x36 image with 2 threads 5 % of its samples/s in the
 * median run and a quarter in the worst of five. A waiting thread spins a little before it sleeps. */
struct pass_barrier {
    pthread_mutex_t lock;
    pthread_cond_t wake;
    int threads, waiting;
    atomic_uint generation;
    bool more;
    bool (*decide)(void *ctx);
    void *ctx;
};
void pass_barrier_init(struct pass_barrier *b, int threads, bool (*decide)(void *ctx), void *ctx);
bool pass_barrier_arrive(struct pass_barrier *b);
void pass_barrier_destroy(struct pass_barrier *b);

/* Progress over `total` units. On a terminal a bar redrawn in place, after one second and at most
 * ten times a second; into a log (stderr not a terminal) a line every ten seconds, so that a long
 * batch run's log says how far it got. */
struct progress {
    const char *label;
    long total;
    atomic_long done;
    atomic_long last_draw_ms;
    double start;
    bool enabled, tty;
    atomic_bool drawn;
};
void progress_init(struct progress *p, const char *label, long total, bool enabled);
void progress_add(struct progress *p, long n);
/* Sets the units done (for time-based runs measured in milliseconds). */
void progress_set(struct progress *p, long done);
void progress_finish(struct progress *p);

/* Ctrl-C: the first SIGINT sets a flag long loops poll (they stop early and the tools write what
 * was computed, marked partial); a second one terminates as usual. */
void interrupt_install(void);
/* Stops the loops as a first Ctrl-C does, from the program itself (a checkpoint it cannot write). */
void interrupt_request(void);
bool interrupted(void);

/* Wall-clock seconds (monotonic). */
double now_seconds(void);
/* The clock a time budget runs on: wall-clock seconds, or (cpu) the CPU seconds the process's
 * threads have used, divided by `threads`, so that another process on the machine does not shift
 * an equal-time comparison: a starved render runs longer and does the same work. */
double budget_seconds(bool cpu, int threads);
int cpu_count(void);

#endif
