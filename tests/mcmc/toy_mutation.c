/* A toy mutation, the whole of one (core/mcmc/mutation.h): every eighth iteration of a worker that
 * draws a small step proposes fresh numbers instead. A uniform proposal has a constant density, so
 * min(1, f(y) / f(x)) keeps the chain's target, and a kernel chosen by the iteration's index, not
 * by the state, keeps it too. Its per-chain state counts the moves it made (checkpointed by the
 * registry as raw bytes). Registered by tests/mcmc/test_mutation.c with one line. */
#include "mcmc/mutation.h"

extern const struct mutation mutation_toy;
int toy_kind; /* its statistics kind, from mutation_register */

static bool applies(const struct worker *wk, const struct chain *c, bool large)
{
    (void)c;
    return !large && wk->n % 8 == 0;
}

static void step(struct worker *wk, struct chain *c, bool large, double t_start)
{
    (void)large;
    struct proposal pr;
    long *moves = mutation_state(c, &mutation_toy);
    double f0 = c->f;
    int tech0 = c->tech;
    mutation_propose(wk, c, true, &pr);             /* fresh numbers, traced and evaluated */
    mutation_decide(wk, c, toy_kind, &pr, t_start); /* acceptance, splats, statistics row */
    *moves += c->f != f0 || c->tech != tech0;
}

const struct mutation mutation_toy = {.name = "toy", .applies = applies, .step = step, .chain_state = sizeof(long)};
