/* Veach's MLT's state (veach.h): set from a connection, a chain's start, and the state in and out
 * of checkpoints (the bidirectional mutation's entry, veach_bidir.c, carries them). */
#include "mcmc/veach.h"
#include "mcmc/splat_ev.h"
#include "path/path_checkpoint.h"

double veach_radiance_factor(const struct vertex *const *x, int s)
{
    double r = 1, d2;
    for (int i = 1; i < s; i++)
        r *= vertex_radiance_factor(x[i], edge_dir(x[i], x[i + 1], &d2), edge_dir(x[i], x[i - 1], &d2));
    return r;
}

bool veach_state_set(struct veach_state *st, const struct path_ctx *pc, const struct vertex *y, int s,
                     const struct vertex *z, int t)
{
    int k = s + t - 1;
    const struct vertex *x[MAX_SUBPATH_VERTS];
    for (int i = 0; i <= k; i++) {
        st->x[i] = i < s ? y[i] : z[k - i];
        x[i] = &st->x[i];
    }
    /* the walks may have gone on from the connection's ends through a delta lobe; the path does not */
    if (s > 0) st->x[s - 1].delta = false;
    st->x[s].delta = st->x[0].delta = st->x[k].delta = false;
    struct connection cn;
    if (!connect_st(pc, y, s, z, t, k, &cn, st->ratios)) return false;
    st->k = k;
    st->s = s;
    st->f = vscale(cn.f, veach_radiance_factor(x, s));
    st->px = cn.px;
    st->py = cn.py;
    double l = luminance(st->f);
    return vfinite(st->f) && isfinite(l) && l > 0;
}

void veach_move_to(struct chain *c, const struct veach_state *st)
{
    struct splat_list l = {.n = 0};
    splat_push(&l, st->px, st->py, st->f);
    move_to(c->img, c, &l, luminance(st->f));
}

void veach_chain_start(struct worker *wk, struct chain *c)
{
    const struct path_ctx *pc = &wk->path_ctx;
    const struct scratch *w = wk->scratch;
    struct veach_state *st = mutation_state(c, &mutation_veach_bidir);
    /* the connections bdpt_splats summed into the seed's target, each with its share of it */
    double sum = 0, pick = -1;
    for (int pass = 0; pass < 2; pass++) {
        double acc = 0;
        for (int t = 1; t <= w->nz; t++)
            for (int s = 0; s <= w->ny; s++) {
                struct connection cn;
                if (s + t - 1 < 1 || s + t - 1 > pc->max_length) continue;
                if (!connect_st(pc, w->emi, s, w->cam, t, s + t - 1, &cn, NULL)) continue;
                double l = luminance(vscale(cn.f, cn.w));
                if (!isfinite(l) || !(l > 0)) continue;
                acc += l;
                if (pass == 1 && acc > pick && veach_state_set(st, pc, w->emi, s, w->cam, t)) {
                    c->cur.n = 0;
                    c->f = 0;
                    veach_move_to(c, st);
                    return;
                }
            }
        sum = acc;
        pick = rng_uniform(&wk->r) * sum;
    }
    c->cur.n = 0; /* no connection: the seed had no light (chain_start draws seeds with light) */
    c->f = 0;
}

void veach_state_save(struct ckpt_buf *b, const struct scene *sc, const struct chain *c, const void *state)
{
    (void)c;
    const struct veach_state *x = state;
    if (!x) return;
    CKPT_PUT(b, x->k);
    CKPT_PUT(b, x->s);
    CKPT_PUT(b, x->f);
    CKPT_PUT(b, x->px);
    CKPT_PUT(b, x->py);
    CKPT_PUT(b, x->ratios);
    ckpt_put_vertices(b, sc, x->x, MAX_SUBPATH_VERTS);
}

bool veach_state_load(struct ckpt_buf *b, const struct scene *sc, struct chain *c, void *state)
{
    (void)c;
    struct veach_state *x = state;
    if (!x) return true;
    CKPT_GET(b, x->k);
    CKPT_GET(b, x->s);
    CKPT_GET(b, x->f);
    CKPT_GET(b, x->px);
    CKPT_GET(b, x->py);
    CKPT_GET(b, x->ratios);
    ckpt_get_vertices(b, sc, x->x, MAX_SUBPATH_VERTS);
    return x->k >= 1 && x->k <= MAX_PATH_LENGTH && x->s >= 0 && x->s <= x->k;
}
