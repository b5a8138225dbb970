/* Veach's MLT's state (veach.h): set from a connection, a chain's start, a proposal's end, the
 * registry's entry that picks the iteration's mutation, and the state in and out of checkpoints. */
#include "mcmc/veach.h"
#include "mcmc/splat_ev.h"
#include "path/path_checkpoint.h"
#include "path/path_form.h"
#include <stdlib.h>

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

double veach_f_at(const struct path_ctx *pc, const struct veach_state *x, int j, struct veach_scratch *w)
{
    if (x->s == j) return luminance(x->f);
    const struct vertex *xp[MAX_SUBPATH_VERTS];
    for (int i = 0; i <= x->k; i++)
        xp[i] = &x->x[i];
    if ((j >= 1 && !path_emitter_form(pc, xp, j, w->xs)) || !path_camera_form(pc, xp, x->k, x->k + 1 - j, w->xz) ||
        !veach_state_set(&w->xm, pc, w->xs, j, w->xz, x->k + 1 - j))
        return 0;
    return luminance(w->xm.f);
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
    struct veach_state *st = mutation_state(c, &mutation_veach);
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

void veach_decide(struct worker *wk, struct chain *c, struct veach_state *x, int kind, bool made, bool refused,
                  double a, double t_start)
{
    const struct veach_state *y = &wk->veach->y;
    double fy = made ? luminance(y->f) : 0;
    struct splat_list l = {.n = 0};
    if (made) splat_push(&l, y->px, y->py, y->f);
    splat_ev(c->img, c, &l, fy, a);
    bool acc = made && rng_uniform(&wk->r) < a;
    int k0 = x->k;
    if (acc) {
        x->k = y->k;
        x->s = y->s;
        x->f = y->f;
        x->px = y->px;
        x->py = y->py;
        for (int i = 0; i <= x->k; i++) { /* the path's own vertices only: a state is 17 kB */
            x->ratios[i] = y->ratios[i];
            x->x[i] = y->x[i];
        }
        veach_move_to(c, x);
    }
    stats_record_dt(wk->st, (enum proposal_kind)kind, k0, made && y->k != k0, made ? abs(y->k - k0) : 0, refused, a,
                    acc, fy > 0, mutation_elapsed(wk, t_start));
}

static bool applies(const struct worker *wk, const struct chain *c, bool large)
{
    (void)c, (void)large;
    return wk->opts->method == MLT_VEACH;
}

static bool wanted(const struct mlt_opts *o) { return o->method == MLT_VEACH; }

static void step(struct worker *wk, struct chain *c, bool large, double t_start)
{
    (void)large;
    struct veach_state *x = mutation_state(c, &mutation_veach);
    const struct mlt_opts *o = wk->opts;
    /* the mixture: each mutation its option's share of the iterations, the rest bidirectional */
    const struct {
        double share;
        void (*step)(struct worker *, struct chain *, struct veach_state *, double);
    } mix[] = {{o->veach_lens, veach_lens_step},
               {o->veach_caustic, veach_caustic_step},
               {o->veach_lens_subpath, veach_lens_subpath_step},
               {o->veach_multichain, veach_multichain_step}};
    double u = rng_uniform(&wk->r), below = 0;
    for (size_t i = 0; i < sizeof mix / sizeof mix[0]; i++)
        if (u < (below += mix[i].share)) {
            mix[i].step(wk, c, x, t_start);
            return;
        }
    veach_bidir_step(wk, c, x, t_start);
}

const struct mutation mutation_veach = {.name = "veach",
                                        .applies = applies,
                                        .step = step,
                                        .chain_state = sizeof(struct veach_state),
                                        .wanted = wanted,
                                        .save = veach_state_save,
                                        .load = veach_state_load};
