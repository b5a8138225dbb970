/* MCTLS, the multiple correlated-try large step (see mctls.h; thesis §4.3, Eq. 4.1-4.7). */
#include "mcmc/mctls.h"
#include "mcmc/mmlt.h"
#include "mcmc/mutation.h"
#include "mcmc/splat_ev.h"
#include "path/connect.h"
#include "sampling/pick.h"
#include <math.h>
#include <string.h>

bool use_mctls(const struct mlt_opts *o, int k)
{
    if (!mlt_multiplexed(o->method)) return false;
    return o->large_step == LARGE_MCTLS || (o->large_step == LARGE_HYBRID && k >= o->hybrid_length);
}

double mctls_accept(double ysum, double xsum) { return xsum > 0 ? fmin(1.0, ysum / xsum) : 1.0; }

double mctls_trials(const struct path_ctx *pc, struct sampler *s, struct scratch *w, int k, double *pi,
                    struct splat_list *sp)
{
    int nz = walk_camera(pc, s, w->cam, k + 1);
    int ny = walk_emitter(pc, s, w->emi, k);
    double sum = 0;
    struct connection c;
    for (int t = 1; t <= k + 1; t++) {
        int sv = k + 1 - t;
        pi[t] = 0;
        sp[t].n = 0;
        if (nz < t || ny < sv) continue;
        w->conn_tried++;
        if (!connect_st(pc, w->emi, sv, w->cam, t, k, &c, NULL)) continue;
        rgb v = mmlt_contribution(&c, k);
        if (!vfinite(v)) {
            w->nf.len[k]++;
            continue;
        }
        w->conn_nonzero += luminance(v) > 0;
        splat_push(&sp[t], c.px, c.py, v);
        pi[t] = splat_luminance(&sp[t]);
        sum += pi[t];
    }
    return sum;
}

/* PITP after an accepted MCTLS step: the chosen technique's subpaths are prefixes of the ones MCTLS
 * traced to full length; one more connection gives their density ratios. */
static void keep_path(const struct path_ctx *pc, struct mmlt_path *x, const struct scratch *w, int k, int t)
{
    x->k = k;
    x->t = t;
    x->s = k + 1 - t;
    memcpy(x->cam, w->cam, (size_t)t * sizeof *x->cam);
    memcpy(x->emi, w->emi, (size_t)x->s * sizeof *x->emi);
    struct connection c;
    connect_st(pc, x->emi, x->s, x->cam, t, k, &c, x->ratios);
}

/* A technique drawn uniformly among the k + 1 (t = 1..k+1) or, counting t = 0, the k + 2 the thesis
 * counts. */
static int draw_technique(int k, bool t0, rng *r)
{
    int n = k + 1 + t0, t = (int)(n * rng_uniform(r));
    return (t < n ? t : n - 1) + !t0;
}

/* Eq. 4.5 with n trials (mlt_opts.mctls_tries): the current state's trials x_1..x_{n-1} drawn with
 * its own technique as x_n, the proposal's y_1..y_n; returns the sum over the y_i and sets *j to
 * the picked one's technique (0 when none has a target; pi[0] is 0, the camera hit) and *xsum. */
static double drawn_trials(const struct path_ctx *pc, struct chain *c, struct scratch *w, struct mctls_buf *b, rng *r,
                           int n, bool t0, int *j, double *xsum)
{
    int k = c->k, tech[MCTLS_MAX_TRIES];
    double wt[MCTLS_MAX_TRIES];
    mctls_trials(pc, &c->pss.base, w, k, b->xpi, b->xsp);
    b->xpi[0] = 0;
    *xsum = b->xpi[c->tech];
    for (int i = 1; i < n; i++)
        *xsum += b->xpi[draw_technique(k, t0, r)];
    pss_begin(&c->pss, true);
    mctls_trials(pc, &c->pss.base, w, k, b->pi, b->sp);
    b->pi[0] = 0;
    double ysum = 0;
    for (int i = 0; i < n; i++) {
        tech[i] = draw_technique(k, t0, r);
        wt[i] = b->pi[tech[i]];
        ysum += wt[i];
    }
    *j = ysum > 0 ? tech[pick_weighted(wt, n, rng_uniform(r))] : 0;
    return ysum;
}

double mctls_step(const struct path_ctx *pc, const struct mlt_opts *o, struct chain *c, struct scratch *w,
                  struct mctls_buf *b, rng *r, struct image *img, bool *acc, bool *changed, bool *nonzero)
{
    int k = c->k, j;
    double ysum;
    if (o->mctls_tries > 0) {
        ysum = drawn_trials(pc, c, w, b, r, o->mctls_tries, o->mctls_count_t0, &j, &c->xsum);
        c->xsum_valid = false;
    } else {
        if (!c->xsum_valid || o->mctls_recompute) {
            c->xsum = mctls_trials(pc, &c->pss.base, w, k, b->xpi, b->xsp);
            c->xsum_valid = true;
        }
        pss_begin(&c->pss, true);
        ysum = mctls_trials(pc, &c->pss.base, w, k, b->pi, b->sp);
        j = ysum > 0 ? pick_weighted(b->pi + 1, k + 1, rng_uniform(r)) + 1 : 0;
    }
    double a = mctls_accept(ysum, c->xsum);
    /* expected values (splat_ev.h); a trial with a target whenever any has one */
    if (ysum > 0) splat_list_weighted(img, &b->sp[j], a * c->scale / b->pi[j], c->dropped);
    owe_current(c, a);
    *nonzero = ysum > 0;
    *acc = ysum > 0 && rng_uniform(r) < a;
    *changed = ysum > 0 && j != c->tech; /* a property of the proposal, not of its acceptance */
    if (*acc) {
        /* the state's technique number: a uniform point of the chosen technique's interval (Eq. 5.6) */
        pss_set(&c->pss, STREAM_TECHNIQUE, 0, mmlt_technique_number(j, k, rng_uniform(r)));
        pss_accept(&c->pss);
        move_to(img, c, &b->sp[j], b->pi[j]);
        c->tech = j;
        c->xsum = ysum;
        c->xsum_valid = o->mctls_tries == 0;
        if (c->x) keep_path(pc, c->x, w, k, j);
    } else {
        pss_reject(&c->pss);
    }
    return a;
}

/* As a mutation (mutation.h): the large steps of the lengths MCTLS is chosen for. */
static bool applies(const struct worker *wk, const struct chain *c, bool large)
{
    return large && use_mctls(wk->opts, c->k);
}

static void step(struct worker *wk, struct chain *c, bool large, double t_start)
{
    (void)large;
    bool acc, changed, nonzero;
    wk->scratch->conn_tried = wk->scratch->conn_nonzero = 0;
    double a =
        mctls_step(&wk->path_ctx, wk->opts, c, wk->scratch, wk->mctls_buf, &wk->r, c->img, &acc, &changed, &nonzero);
    mutation_take_connections(wk);
    stats_record(wk->st, PROPOSAL_MCTLS, c->k, changed, a, acc, nonzero, mutation_elapsed(wk, t_start));
}

const struct mutation mutation_mctls = {.name = "mctls", .applies = applies, .step = step};
