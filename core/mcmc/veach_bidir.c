/* Veach's bidirectional mutation (Veach & Guibas 1997, §5.3.1; docs/veach.md): delete the vertices
 * x_{l+1}..x_{m-1} of the chain's path (l = -1 or m = k + 1 delete an end too), add k_a - 1 new
 * ones by extending the kept prefix from x_l with s' emitter-walk steps and the kept suffix from x_m
 * with t' camera-walk steps (fresh numbers), and connect them. With the kept vertices' densities
 * the same in x and y, f(y) / T(x -> y) = Q(y) n(y) / (p_d(x) p_a(k_a | k_d)) up to their product,
 * Q(y) = lum f(y) / sum over the splits j the added segment could have been sampled with of p_j(y),
 * n(y) the number of those splits; Q comes from connect_st's ratios at the split actually
 * connected, so the current state needs no new evaluation.
 *
 * A kept end that scatters through a delta lobe is refused (in x, or in y after the extension):
 * the MIS code gives such a vertex's density in solid angle, not area, so the kept densities would
 * not cancel; refusing it in y as in x keeps the move and its reverse possible together. */
#include "mcmc/veach.h"
#include "path/path_form.h"
#include <math.h>
#include <stdlib.h>

/* Deleted edges k_d (the harness's defaults, of the shape Veach describes: short deletions first) */
static double w_del(int kd) { return kd == 1 ? 0.25 : kd == 2 ? 0.5 : ldexp(1.0, -kd); }
/* Added edges k_a, favouring k_a = k_d */
static double w_add(int d)
{
    d = d < 0 ? -d : d;
    return d == 0 ? 0.5 : d == 1 ? 0.15 : 0.2 * ldexp(1.0, -d);
}

/* The sum of w(a - shift) over a = lo..hi, and the a that u in [0, 1) picks in proportion to it
 * (the last when rounding leaves u past the sum): the draws and the probabilities of the moves
 * and of their reverses share them. */
static double w_sum(double (*w)(int), int lo, int hi, int shift)
{
    double z = 0;
    for (int a = lo; a <= hi; a++)
        z += w(a - shift);
    return z;
}
static int w_pick(double (*w)(int), int lo, int hi, int shift, double u)
{
    u *= w_sum(w, lo, hi, shift);
    int a = lo;
    while (a < hi && (u -= w(a - shift)) >= 0)
        a++;
    return a;
}

/* The probability of deleting edges l..m (k_d = m - l) from a path of length k: k_d in proportion to
 * w_del over 1..k + 2, then l uniform over the k + 3 - k_d places. */
static double p_del(int k, int kd) { return w_del(kd) / w_sum(w_del, 1, k + 2, 0) / (k + 3 - kd); }

/* The added lengths a move deleting k_d edges at l..m of a path of length k may add: a new camera
 * vertex needs an edge (m = k + 1), a new path at least one edge, and the result at most max_len;
 * the same set for the reverse move (docs/veach.md). */
static void add_range(int k, int l, int m, int kd, int max_len, int *lo, int *hi)
{
    int base = 1 + (m == k + 1) + (l == -1 && m == k + 1);
    *lo = base > 1 + kd - k ? base : 1 + kd - k;
    *hi = max_len - (k - kd);
}

static double p_add(int ka, int kd, int lo, int hi) { return w_add(ka - kd) / w_sum(w_add, lo, hi, kd); }

/* Q of a path over the splits j = l + 1 .. hi of the segment it has between x_l and x_m. */
static double q_of(const struct veach_state *st, int l, int hi)
{
    double sum = 0;
    for (int j = l + 1; j <= hi; j++)
        sum += st->ratios[j];
    return sum > 0 ? luminance(st->f) / sum : INFINITY;
}

struct bidir_move {
    int kd, l, m, ka, ky, j; /* deleted edges l..m, added edges, new length, its split */
    double fwd, rev;         /* p_d p_a / n of the move and of its reverse */
};

/* Draws the move's numbers (kd, l, ka, the split) from the chain's generator; false when no length
 * can be added there. */
static bool draw_move(rng *r, int k, int max_len, struct bidir_move *mv)
{
    mv->kd = w_pick(w_del, 1, k + 2, 0, rng_uniform(r));
    mv->l = -1 + (int)(rng_uniform(r) * (k + 3 - mv->kd));
    if (mv->l > k + 1 - mv->kd) mv->l = k + 1 - mv->kd;
    mv->m = mv->l + mv->kd;
    int lo, hi;
    add_range(k, mv->l, mv->m, mv->kd, max_len, &lo, &hi);
    if (lo > hi) return false;
    mv->ka = w_pick(w_add, lo, hi, mv->kd, rng_uniform(r));
    mv->ky = k - mv->kd + mv->ka;
    int top_y = mv->l + mv->ka < mv->ky ? mv->l + mv->ka : mv->ky, top_x = mv->m < k ? mv->m : k;
    int ny = top_y - mv->l, nx = top_x - mv->l; /* the splits each path's segment has */
    mv->j = mv->l + 1 + (int)(rng_uniform(r) * ny);
    if (mv->j > top_y) mv->j = top_y;
    mv->fwd = p_del(k, mv->kd) * p_add(mv->ka, mv->kd, lo, hi) / ny;
    mv->rev = p_del(mv->ky, mv->ka) * p_add(mv->kd, mv->ka, lo, hi) / nx;
    return true;
}

/* The proposal y of move mv from x into *y; false when it cannot be made. */
static bool make_path(const struct path_ctx *pc, struct sampler *fresh, const struct veach_state *x,
                      const struct bidir_move *mv, struct veach_state *y, struct vertex *ys, struct vertex *zs)
{
    const struct vertex *xp[MAX_SUBPATH_VERTS];
    for (int i = 0; i <= x->k; i++)
        xp[i] = &x->x[i];
    int s = mv->j, t = mv->ky + 1 - s, keep_z = x->k - mv->m + 1;
    if (mv->l >= 0 && !path_emitter_form(pc, xp, mv->l + 1, ys)) return false;
    if (s > mv->l + 1) {
        int n =
            mv->l >= 0 ? walk_extend_from(pc, fresh, ys, mv->l + 1, s, STREAM_EMITTER) : walk_emitter(pc, fresh, ys, s);
        if (n != s) return false;
    }
    if (keep_z > 0 && !path_camera_form(pc, xp, x->k, keep_z, zs)) return false;
    if (t > keep_z) {
        int n = keep_z > 0 ? walk_extend_from(pc, fresh, zs, keep_z, t, STREAM_CAMERA) : walk_camera(pc, fresh, zs, t);
        if (n != t) return false;
    }
    if (!veach_state_set(y, pc, ys, s, zs, t)) return false;
    /* the kept ends must not scatter through a delta lobe in y either (the reverse move's refusal) */
    return !(mv->l >= 0 && y->x[mv->l].delta) && !(mv->m <= x->k && y->x[mv->l + mv->ka].delta);
}

void veach_bidir_step(struct worker *wk, struct chain *c, struct veach_state *x, double t_start)
{
    struct veach_scratch *w = wk->veach;
    struct sampler_rng fresh;
    sampler_rng_init(&fresh, &wk->r);
    struct bidir_move mv;
    /* l = k would keep the camera vertex in the prefix (no move's reverse has it: y's camera vertex
     * lies past l) */
    bool refused = !draw_move(&wk->r, x->k, wk->path_ctx.max_length, &mv) || mv.l >= x->k ||
                   (mv.l >= 0 && x->x[mv.l].delta) || (mv.m <= x->k && x->x[mv.m].delta);
    bool made = !refused && make_path(&wk->path_ctx, &fresh.base, x, &mv, &w->y, w->ys, w->zs);
    double a = 0;
    if (made) {
        int top_y = mv.l + mv.ka < mv.ky ? mv.l + mv.ka : mv.ky, top_x = mv.m < x->k ? mv.m : x->k;
        double qy = q_of(&w->y, mv.l, top_y), qx = q_of(x, mv.l, top_x);
        double fwd = mv.fwd * (wk->opts->veach_broken_t && mv.ka > mv.kd ? 1.1 : 1);
        a = qx < INFINITY && qy < INFINITY ? fmin(1.0, (qy * mv.rev) / (qx * fwd)) : 0;
        if (!(a >= 0)) a = 0;
    }
    veach_decide(wk, c, x, PROPOSAL_BIDIR, made, refused, a, t_start);
}
