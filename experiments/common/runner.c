/* The interleaved loop (runner.h). */
#include "common/runner.h"

void runner_each(const struct runner_grid *g, void (*run)(void *ctx, int seed, int budget, int method), void *ctx)
{
    for (int s = 0; s < g->seeds; s++)
        for (int b = 0; b < g->budgets; b++)
            for (int m = 0; m < g->methods; m++)
                if (!g->skip || !g->skip[m]) run(ctx, s, b, m);
}
