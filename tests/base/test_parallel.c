/* The pass barrier that time-budgeted PT and BDPT runs use between passes. */
#include "base/parallel.h"
#include <criterion/criterion.h>

#define THREADS 4
#define PASSES 500

struct passes {
    struct pass_barrier bar;
    atomic_int work[THREADS]; /* passes each thread has finished */
    int pass;                 /* written by decide only, read by everyone after the barrier */
    int decisions;
    atomic_int bad;
};

/* Runs alone, after every thread finished the current pass and before any starts the next. */
static bool decide(void *p)
{
    struct passes *s = p;
    s->decisions++;
    for (int t = 0; t < THREADS; t++)
        if (atomic_load(&s->work[t]) != s->pass + 1) atomic_fetch_add(&s->bad, 1);
    if (++s->pass == PASSES) return false;
    return true;
}

static void worker(int tid, void *p)
{
    struct passes *s = p;
    do {
        /* A thread that ran ahead into the next pass would be seen by decide, or would see a
         * pass number other than its own count. */
        if (s->pass != atomic_load(&s->work[tid])) atomic_fetch_add(&s->bad, 1);
        atomic_fetch_add(&s->work[tid], 1);
    } while (pass_barrier_arrive(&s->bar) && atomic_load(&s->work[tid]) <= PASSES); /* bounded if broken */
}

Test(parallel, pass_barrier_runs_every_thread_through_every_pass_in_step, .timeout = 30)
{
    static struct passes s;
    pass_barrier_init(&s.bar, THREADS, decide, &s);
    parallel_run(THREADS, worker, &s);
    pass_barrier_destroy(&s.bar);
    cr_assert_eq(s.decisions, PASSES, "decide ran %d times for %d passes", s.decisions, PASSES);
    for (int t = 0; t < THREADS; t++)
        cr_assert_eq(atomic_load(&s.work[t]), PASSES, "thread %d", t);
    cr_assert_eq(atomic_load(&s.bad), 0, "%d passes out of step", atomic_load(&s.bad));
}
