/* The registry of mutations (mutation.h): the built-in table, the ones registered at run time, the
 * walk of one iteration, and the chains' per-mutation state. */
#include "base/util.h"
#include "mcmc/mutation.h"
#include <stdlib.h>

/* The built-in mutations in the order they are tried: one line each. */
static const struct mutation *const builtin[] = {
    &mutation_veach, /* --method mlt: Veach's mutations, every iteration (veach.c) */
    &mutation_mctls, /* large steps at MCTLS's lengths (mctls.c) */
    &mutation_pitp,  /* before every small step under PITP (pitp_step.c) */
    &mutation_fused, /* --fused: a share of the small steps, the others made by it (fused.c) */
    &mutation_large, /* the other large steps: fresh numbers (pss_step.c) */
    &mutation_small, /* the small step (pss_step.c) */
};
#define BUILTIN (int)(sizeof builtin / sizeof builtin[0])

static const struct mutation *added[MUTATIONS_ADDED_MAX];
static int nadded;

static int count(void) { return nadded + BUILTIN; }
static const struct mutation *entry(int i) { return i < nadded ? added[i] : builtin[i - nadded]; }

int mutation_register(const struct mutation *m)
{
    if (nadded == MUTATIONS_ADDED_MAX) return -1;
    int kind = proposal_kind_add(m->name);
    if (kind >= 0) added[nadded++] = m;
    return kind;
}

void mutations_iterate(struct worker *wk, struct chain *c, bool large, double t_start)
{
    wk->tech_before = c->tech;
    for (int i = 0; i < count(); i++) {
        const struct mutation *m = entry(i);
        if (!m->applies(wk, c, large)) continue;
        m->step(wk, c, large, t_start);
        if (!m->before) return;
    }
}

void *mutation_state(const struct chain *c, const struct mutation *m)
{
    for (int i = 0; i < count(); i++)
        if (entry(i) == m) return c->state[i];
    return NULL;
}

void mutations_chain_alloc(struct chain *c, const struct mlt_opts *o)
{
    for (int i = 0; i < count(); i++) {
        const struct mutation *m = entry(i);
        if (m->chain_state && !c->state[i] && (!m->wanted || m->wanted(o))) c->state[i] = xcalloc(1, m->chain_state);
    }
}

void mutations_chain_free(struct chain *c)
{
    for (int i = 0; i < count(); i++) {
        free(c->state[i]);
        c->state[i] = NULL;
    }
}

void mutations_chain_save(struct ckpt_buf *b, const struct scene *sc, const struct chain *c)
{
    for (int i = 0; i < count(); i++) {
        const struct mutation *m = entry(i);
        if (m->save)
            m->save(b, sc, c, c->state[i]);
        else if (m->chain_state && c->state[i])
            ckpt_put(b, c->state[i], m->chain_state);
    }
}

bool mutations_chain_load(struct ckpt_buf *b, const struct scene *sc, struct chain *c)
{
    for (int i = 0; i < count(); i++) {
        const struct mutation *m = entry(i);
        if (m->load && !m->load(b, sc, c, c->state[i])) return false;
        if (!m->load && m->chain_state && c->state[i]) ckpt_get(b, c->state[i], m->chain_state);
    }
    return !b->short_read;
}
