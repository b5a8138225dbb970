/* Fused perturbations (Otsu, Kaplanyan, Hanika, Dachsbacher and Hachisuka 2017, "Fusing state spaces
 * for Markov chain Monte Carlo rendering"; thesis §7.1's open door; docs/fused.md): a share
 * mlt_opts.fused_rate of an MMLT or PITP chain's small steps perturbs the chain's path in path space
 * with Veach's lens, caustic or multi-chain perturbation (veach_lens.c, veach_caustic.c,
 * veach_multichain.c), and the inverse of the
 * chain's technique (path_invert.c) maps the perturbed path y back to primary sample space: the
 * proposal is those numbers, with the technique number and every number the path does not use kept.
 *
 * Acceptance. The chain's target in primary sample space is (k + 1) w_t C_t = (k + 1) w_t f / p_t,
 * and the inverse's numbers have density T(x -> y) / p_t(y) (the inverse is measure-preserving, the
 * thesis's Eq. 5.9-5.14), so p_t cancels: a = f(y) w_t(y) T(y -> x) / (f(x) w_t(x) T(x -> y)).
 * Veach's perturbations give T(y -> x) / T(x -> y) = p_j(x) / p_j(y) times 1 (lens, split j = m),
 * p(omega') / p(omega) (caustic, j = k) or the product of those over the turned vertices
 * (multi-chain, j = m): with the targets' ratio that is
 * a = target(y) / target(x) * (p_j / p_t)(x) / (p_j / p_t)(y) * that factor,
 * from the density ratios both evaluations already hold. A path the technique cannot produce (an
 * inversion that fails, or numbers whose walk does not retrace y) is refused: such a y is never a
 * state of the chain, so no move from it needs its reverse (docs/fused.md argues the pair). */
#include "mcmc/fused.h"
#include "base/util.h"
#include "mcmc/mutation.h"
#include "path/path_form.h"
#include <math.h>

/* The writer an inversion puts its numbers through: into the chain's proposal (pss_set, restored
 * on rejection), the fresh numbers of discrete inversions from the chain's own stream. */
struct pss_writer {
    struct sampler base;
    struct pss_sampler *p;
};

static double writer_next(struct sampler *s, enum dim_kind kind)
{
    (void)s, (void)kind;
    return NAN; /* an inversion never reads: a NaN number fails whatever used it */
}

static void writer_put(struct sampler *s, enum dim_kind kind, double u)
{
    (void)kind;
    pss_set(((struct pss_writer *)s)->p, s->stream, sampler_index(s), u);
}

static double writer_fresh(struct sampler *s) { return rng_uniform(&((struct pss_writer *)s)->p->r); }
static const struct sampler_ops writer_ops = {writer_next, writer_put, writer_fresh};

void fused_state_of(struct veach_state *st, const struct mmlt_path *x, double px, double py)
{
    int k = x->k, s = x->s;
    for (int i = 0; i <= k; i++)
        st->x[i] = i < s ? x->emi[i] : x->cam[k - i];
    if (s > 0) st->x[s - 1].delta = false;
    st->x[s].delta = st->x[0].delta = st->x[k].delta = false;
    st->k = k;
    st->s = s;
    st->px = px;
    st->py = py;
}

/* Whether the emitter subpath of a path of x's technique, moved from x'_lo on, has a moved vertex:
 * else its numbers and vertices are kept, and neither formed nor inverted. */
static bool emitter_moved(const struct mmlt_path *x, int lo) { return x->s > 0 && (lo == 0 || x->s > lo); }

bool fused_retraced(const struct mmlt_path *y, int lo, const struct veach_scratch *w, double tol)
{
    for (int i = 0; i < y->t; i++)
        if (!vertex_same(&y->cam[i], &w->xz[i], tol)) return false;
    for (int i = 0; emitter_moved(y, lo) && i < y->s; i++)
        if (!vertex_same(&y->emi[i], &w->xs[i], tol)) return false;
    return true;
}

bool fused_invert(const struct path_ctx *pc, const struct mmlt_path *x, const struct vertex *const *yp, int lo,
                  struct veach_scratch *w, struct sampler *wr)
{
    /* the emitter subpath's blocks before the one that reaches x'_lo keep their numbers: its
     * vertices up to x_{lo-1} are x's, which those numbers reach */
    int from = lo > 0 ? lo - 1 : 0;
    bool emitter = emitter_moved(x, lo);
    return path_camera_form(pc, yp, x->k, x->t, w->xz) && (!emitter || path_emitter_form(pc, yp, x->s, w->xs)) &&
           invert_camera(pc, w->xz, x->t, 0, wr) && (!emitter || invert_emitter(pc, w->xs, x->s, from, wr));
}

/* The perturbed path yp (moved from x'_lo on) inverted into the proposal's numbers, every other
 * number kept (the technique number, the blocks before the move), and traced forward into
 * wk->spare; pr->f its target. False when the technique cannot produce it. */
static bool invert_and_trace(struct worker *wk, struct chain *c, const struct vertex *const *yp, int lo,
                             struct proposal *pr)
{
    const struct path_ctx *pc = &wk->path_ctx;
    struct pss_writer pw = {{&writer_ops, 0, 0, 0}, &c->pss};
    const struct mmlt_path *x = c->x;
    if (!fused_invert(pc, x, yp, lo, wk->veach, &pw.base)) return false;
    /* an emitter subpath before the first moved vertex keeps its numbers, so its walk would give
     * its vertices bit for bit: they are copied, not traced */
    bool keep = !emitter_moved(x, lo);
    wk->scratch->conn_tried = wk->scratch->conn_nonzero = 0;
    pr->f = mmlt_eval_state_keep(pc, &c->pss.base, pr->k, keep ? x : NULL, wk->spare, &wk->prop, &wk->scratch->nf);
    pr->tech = wk->spare->t;
    pr->complete = wk->spare->complete;
    wk->scratch->conn_tried += pr->complete;
    wk->scratch->conn_nonzero += pr->complete && pr->f > 0;
    mutation_take_connections(wk);
    if (pr->tech != c->tech || !pr->complete) return false;
    double tol = 1e-4 * maxd(1.0, vlen(vsub(pc->sc->bbox_max, pc->sc->bbox_min)));
    return fused_retraced(wk->spare, lo, wk->veach, tol);
}

static bool applies(const struct worker *wk, const struct chain *c, bool large)
{
    (void)c;
    return !large && wk->multiplexed && wk->opts->fused != FUSED_NONE;
}

static void step(struct worker *wk, struct chain *c, bool large, double t_start)
{
    const struct mlt_opts *o = wk->opts;
    double u = rng_uniform(&wk->r);
    if (!(u < o->fused_rate)) {
        mutation_small.step(wk, c, large, t_start);
        return;
    }
    /* which perturbation: one of the set's, with equal probabilities */
    int set[3], n = 0;
    for (int b = 0; b < 3; b++)
        if (o->fused & (1 << b)) set[n++] = 1 << b;
    int i = (int)(n * u / o->fused_rate), move = set[i < n ? i : n - 1];
    const struct path_ctx *pc = &wk->path_ctx;
    struct veach_scratch *w = wk->veach;
    struct veach_state *xs = &w->xm;
    struct proposal pr = {.f = 0, .tr = 1, .k = c->k, .tech = c->tech, .complete = false, .failed = true};
    pss_begin_kept(&c->pss);
    if (c->f > 0 && c->cur.n > 0) {
        fused_state_of(xs, c->x, c->cur.s[0].px, c->cur.s[0].py);
        int m = move == FUSED_LENS      ? veach_lens_vertex(xs)
                : move == FUSED_CAUSTIC ? veach_caustic_vertex(xs)
                                        : veach_multichain_vertex(xs);
        int j = move == FUSED_CAUSTIC ? xs->k : m;
        double p_old = 1, p_new = 1;
        const struct vertex *yp[MAX_SUBPATH_VERTS];
        bool made = m >= 0 && (move == FUSED_LENS      ? veach_lens_perturb(pc, &wk->r, xs, m, w, yp)
                               : move == FUSED_CAUSTIC ? veach_caustic_perturb(pc, &wk->r, xs, m, w, &p_old, &p_new, yp)
                                                       : veach_multichain_perturb(pc, &wk->r, xs, m, w, &p_new, yp));
        /* the one edge no ray of the perturbation followed, x'_{j-1} x'_j: occluded, y has no
         * contribution, and neither inversion nor trace is needed to refuse it */
        bool seen = made && visible(pc->sc, yp[j - 1], yp[j]);
        if (made && !seen) pr.failed = false;
        /* the first moved vertex: x'_m, or after the caustic perturbation's x_m x'_{m+1} */
        bool inverted = seen && invert_and_trace(wk, c, yp, move == FUSED_CAUSTIC ? m + 1 : m, &pr);
        wk->st->fused_inverted += seen;
        wk->st->fused_not_inverted += seen && !inverted;
        if (inverted) {
            double rx = c->x->ratios[j], ry = wk->spare->ratios[j];
            pr.failed = !(rx > 0 && ry > 0 && p_old > 0);
            pr.tr = pr.failed ? 0 : rx / ry * p_new / p_old;
            if (o->lens_broken_t && wk->prop.n > 0 && wk->prop.s[0].px > xs->px)
                pr.tr /= 1.1; /* tests only: a wrong T(x -> y) */
        }
    }
    if (pr.failed) pr.f = 0;
    mutation_decide(wk, c,
                    move == FUSED_LENS      ? PROPOSAL_FUSED_LENS
                    : move == FUSED_CAUSTIC ? PROPOSAL_FUSED_CAUSTIC
                                            : PROPOSAL_FUSED_MULTICHAIN,
                    &pr, t_start);
}

const struct mutation mutation_fused = {.name = "fused", .applies = applies, .step = step};
