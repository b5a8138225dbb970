/* PITP's technique perturbation as a mutation (mutation.h; pitp.h): before every small step of a
 * PITP chain (or a share pitp_rate of them, mlt.h), always accepted; MMLT's small step then starts
 * from the current path in the new technique's form. Its per-chain state is the path in its
 * technique's form (chain.x), which this file also checkpoints. */
#include "mcmc/mutation.h"
#include "mcmc/splat_ev.h"
#include "path/path_checkpoint.h"
#include <stdlib.h>

static bool applies(const struct worker *wk, const struct chain *c, bool large)
{
    (void)c;
    return wk->pitp && !large && wk->opts->pitp_rate > 0;
}

static void step(struct worker *wk, struct chain *c, bool large, double t_start)
{
    (void)large, (void)t_start; /* not timed: its time is the small step's */
    /* --pitp-rate: below 1 the worker's generator decides (the thesis's 1 draws nothing) */
    double rate = wk->opts->pitp_rate;
    if (rate < 1 && !(rng_uniform(&wk->r) < rate)) return;
    int s_new;
    double accept;
    struct connection conn;
    bool conn_new;
    enum pitp_outcome outcome = pitp_perturb(&wk->path_ctx, &c->pss, c->x, wk->pitp_scratch, rng_uniform(&wk->r),
                                             &s_new, &accept, &conn, &conn_new, &wk->scratch->nf);
    int dtech = abs(s_new - c->x->s);
    if (outcome == PITP_MOVED) {
        dtech = abs(c->k + 1 - s_new - c->tech);
        c->tech = c->x->t;
        c->xsum_valid = false;
        /* controlled steps start from the current path in the new technique's form */
        if (wk->track) ctrl_path_capture(c->path, c->x->cam, c->x->t, c->x->emi, c->x->s);
        if (conn_new) {
            /* the target changed with the technique (refraction, delta vertices): the state's
             * splat and target follow */
            struct splat_list l;
            l.n = 0;
            splat_push(&l, conn.px, conn.py, mmlt_contribution(&conn, c->k));
            move_to(c->img, c, &l, splat_luminance(&l));
        }
    }
    stats_record_dt(wk->st, PROPOSAL_PITP, c->k, dtech != 0, dtech, outcome == PITP_FAILED, accept,
                    outcome == PITP_SAME || outcome == PITP_MOVED, true, 0);
}

static void save(struct ckpt_buf *b, const struct scene *sc, const struct chain *c, const void *state)
{
    (void)state;
    if (!c->x) return;
    CKPT_PUT(b, c->x->k);
    CKPT_PUT(b, c->x->t);
    CKPT_PUT(b, c->x->s);
    CKPT_PUT(b, c->x->complete);
    CKPT_PUT(b, c->x->ratios);
    ckpt_put_vertices(b, sc, c->x->cam, MAX_SUBPATH_VERTS);
    ckpt_put_vertices(b, sc, c->x->emi, MAX_SUBPATH_VERTS);
}

/* The counts that later index arrays are checked: a crafted file is refused, not written through. */
static bool load(struct ckpt_buf *b, const struct scene *sc, struct chain *c, void *state)
{
    (void)state;
    struct mmlt_path *x = c->x;
    if (!x) return true;
    CKPT_GET(b, x->k);
    CKPT_GET(b, x->t);
    CKPT_GET(b, x->s);
    CKPT_GET(b, x->complete);
    CKPT_GET(b, x->ratios);
    ckpt_get_vertices(b, sc, x->cam, MAX_SUBPATH_VERTS);
    ckpt_get_vertices(b, sc, x->emi, MAX_SUBPATH_VERTS);
    return x->k >= 0 && x->k <= MAX_PATH_LENGTH && x->t >= 0 && x->t <= MAX_SUBPATH_VERTS && x->s >= 0 &&
           x->s <= MAX_SUBPATH_VERTS;
}

const struct mutation mutation_pitp = {
    .name = "pitp", .before = true, .applies = applies, .step = step, .save = save, .load = load};
