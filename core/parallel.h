/* Worker threads and a progress bar on stderr. Core code never prints elsewhere. */
#ifndef PARALLEL_H
#define PARALLEL_H

#include <stdatomic.h>
#include <stdbool.h>

/* Runs fn(tid, ctx) on `threads` threads (tid 0 on the caller's thread) and joins them. */
void parallel_run(int threads, void (*fn)(int tid, void *ctx), void *ctx);

/* Progress over `total` units; drawn only after one second and at most ten times a second. */
struct progress {
    const char *label;
    long total;
    atomic_long done;
    atomic_long last_draw_ms;
    double start;
    bool enabled;
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
bool interrupted(void);

/* Wall-clock seconds (monotonic). */
double now_seconds(void);
int cpu_count(void);

#endif
