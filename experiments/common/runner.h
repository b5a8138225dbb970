/* The loop of an experiment over seeds x budgets x methods, interleaved: seed 1 of every budget and
 * method, then seed 2, ...; so a change in the machine's load during the runs falls on every method
 * alike, not on the one that happened to run at the time. Each cell is one call of the tool's run
 * function, which renders (in-process or through a subprocess) and keeps its measurements. */
#ifndef RUNNER_H
#define RUNNER_H

#include <stdbool.h>

struct runner_grid {
    int seeds, budgets, methods;
    const bool *skip; /* [methods]: true for a method not run (NULL: every method runs) */
};

/* Calls run(ctx, seed, budget, method) for every cell, seed outermost and method innermost
 * (0-based indices). */
void runner_each(const struct runner_grid *g, void (*run)(void *ctx, int seed, int budget, int method), void *ctx);

#endif
