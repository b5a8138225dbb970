/* The chains' recorder (core/stats/chain_trace.h) and the stuck rule of core/stats/mixing.h: exact
 * answers on made-up chains. */
#include <criterion/criterion.h>

#include "stats/chain_rhat.h"
#include "stats/mixing.h"
#include <math.h>
#include <stdlib.h>

/* The values held are those of iterations 0, s, 2s, ... at every moment, s doubling as it fills. */
Test(chain_trace, thinning_keeps_every_stride_th_iteration)
{
    struct chain_trace *t = malloc(sizeof *t);
    trace_init(t, 3);
    for (long i = 0; i < 100000; i++) {
        if (trace_step(t, i % 3 == 0)) trace_keep(t, (double)i, -(double)i);
        cr_assert(t->len >= 1 && t->len < TRACE_CAP);
        cr_assert_eq((long)t->contrib[t->len - 1], (t->len - 1) * t->stride, "at %ld", i);
    }
    cr_assert_eq(t->stride, 32); /* 100000 / 4096 rounded up to a power of two */
    for (int i = 0; i < t->len; i++)
        cr_assert_eq((long)t->target[i], -i * t->stride);
    cr_assert_eq(t->n, 100000);
    cr_assert_eq(t->moved, 33334);
    cr_assert_eq(t->longest, 2);
    free(t);
}

/* Ties share their average rank: the normal scores of {5, 1, 5, 3} are those of ranks 3.5, 1, 3.5, 2. */
Test(chain_trace, rank_normalisation_averages_ties)
{
    double x[] = {5, 1, 5, 3}, z[4];
    rank_normalise(x, 4, z);
    cr_assert_float_eq(z[0], z[2], 1e-15);
    cr_assert(z[1] < z[3] && z[3] < z[0]);
    /* Phi^-1((r - 3/8) / (4 + 1/4)) */
    cr_assert_float_eq(z[0], 0.6289, 1e-4);
    cr_assert_float_eq(z[1], -1.0491, 1e-4);
    cr_assert_float_eq(z[3], -0.2993, 1e-4);
}

/* Three chains moving every iteration and one that never moves, 20 000 iterations each: the still
 * one is stuck (its run is the whole chain), the others not; the rows say so. */
Test(chain_trace, a_chain_that_never_moves_is_stuck)
{
    enum { M = 4 };
    long n = 20000;
    struct chain_trace *t = malloc(M * sizeof *t);
    for (int c = 0; c < M; c++) {
        trace_init(&t[c], 0); /* PSSMLT-like: one group, the all row only */
        for (long i = 0; i < n; i++) {
            bool moved = c < M - 1;
            double v = moved ? sin(0.37 * (double)i + c) : 0.5;
            if (trace_step(&t[c], moved)) trace_keep(&t[c], v, v + 2);
        }
    }
    struct mixing_row rows[2];
    int nr = mixing_rows(t, M, rows, 2);
    cr_assert_eq(nr, 1);
    cr_assert_eq(rows[0].longest_max, n);
    cr_assert_float_eq(rows[0].stuck_share, 0.25, 1e-12);
    cr_assert(rows[0].warn & MIXING_STUCK);
    char line[512];
    cr_assert(mixing_warning_line(rows, nr, line, sizeof line));
    cr_assert(strstr(line, "stuck chains at all"), "%s", line);
    /* without the still chain: nothing stuck */
    nr = mixing_rows(t, M - 1, rows, 2);
    cr_assert_float_eq(rows[0].stuck_share, 0, 1e-12);
    cr_assert(!(rows[0].warn & MIXING_STUCK));
    free(t);
}

/* MMLT's rows: one per length present, then the all row over them. */
Test(chain_trace, rows_per_length_and_all)
{
    struct chain_trace *t = malloc(4 * sizeof *t);
    for (int c = 0; c < 4; c++) {
        trace_init(&t[c], 1 + c % 2);
        for (long i = 0; i < 1000; i++)
            if (trace_step(&t[c], true)) trace_keep(&t[c], sin(0.37 * (double)i + c), cos(0.11 * (double)i + c));
    }
    struct mixing_row rows[3];
    int nr = mixing_rows(t, 4, rows, 3);
    cr_assert_eq(nr, 3);
    cr_assert_eq(rows[0].k, 1);
    cr_assert_eq(rows[1].k, 2);
    cr_assert_eq(rows[2].k, -1);
    cr_assert_eq(rows[2].chains, 4);
    cr_assert_eq(rows[2].draws, 4000);
    cr_assert_float_eq(rows[2].ess_total, rows[0].ess_total + rows[1].ess_total, 1e-9);
    free(t);
}
