/* The steps every method makes (mutation.h): the large step of fresh numbers and the small step,
 * each traced through the primary-sample-space sampler or, for the controlled and root small steps
 * (thesis §5.3, controlled_step.h), through the controlled one, then accepted with
 * min(1, f(v) T(v->u) / (f(u) T(u->v))) (MMLT paper Eq. 17-20) and splatted with expected values
 * (splat_ev.c). */
#include "base/util.h"
#include "mcmc/mutation.h"
#include "mcmc/splat_ev.h"
#include "mcmc/tech_split.h"
#include <stdlib.h>

double mutation_elapsed(const struct worker *wk, double t_start)
{
    return wk->opts->time_proposals ? now_seconds() - t_start : 0;
}

void mutation_take_connections(struct worker *wk)
{
    /* the statistics are in the checkpoint; the scratch is not */
    wk->st->conn_tried += wk->scratch->conn_tried;
    wk->st->conn_nonzero += wk->scratch->conn_nonzero;
    wk->scratch->conn_tried = wk->scratch->conn_nonzero = 0;
}

/* The one dispatch point of the small-step kind: a controlled or root step traces the proposal
 * through the controlled sampler, which also yields the kernel's ratio T(v->u) / T(u->v); the
 * lazy primary-sample-space step's is 1. */
void mutation_propose(struct worker *wk, struct chain *c, bool large, struct proposal *pr)
{
    const struct mlt_opts *o = wk->opts;
    struct ctrl_sampler *cs = large ? NULL : wk->ctrl;
    pss_begin(&c->pss, large);
    if (cs) ctrl_begin(cs, &c->pss, c->path, wk->spare->cam, wk->spare->emi, o->small_step);
    wk->scratch->conn_tried = wk->scratch->conn_nonzero = 0; /* the chain starts' and seed pass's are not counted */
    pr->k = c->k;
    pr->tr = 1;
    pr->failed = false;
    if (large && o->one_chain) one_chain_length(wk, pr);
    pr->f = eval_state(o->method, &wk->path_ctx, cs ? &cs->base : &c->pss.base, wk->scratch, pr->k, wk->spare,
                       &wk->prop, &pr->tech, &pr->complete);
    mutation_take_connections(wk);
    if (wk->tech)
        tech_split_record(wk->tech, &wk->path_ctx, wk->scratch, wk->multiplexed ? c->k : 0, pr->tech, &wk->prop, false);
    if (cs) pr->tr = ctrl_finish(cs, pr->complete);
    if (cs && cs->fail != CTRL_OK) wk->ctrl_fail[cs->fail - 1]++;
    if (o->ctrl_unit_ratio && pr->tr > 0) pr->tr = 1;
    if (pr->tr == 0) pr->f = 0; /* an impossible inversion: nothing this proposal could splat */
}

/* Angle statistics of a small step (stats/angle_change.h): the proposal's subpaths against the
 * current ones, when they are of the same split. */
static void record_angle(struct worker *wk, const struct chain *c, const struct proposal *pr)
{
    const struct ctrl_path *cur = c->path;
    double dpsi;
    if (pr->complete && pr->tech == c->tech &&
        angle_change(cur->cam, cur->t, cur->emi, cur->s, wk->spare->cam, wk->spare->emi, &dpsi))
        angle_acc_add(wk->angle, c->cur.s[0].px, c->cur.s[0].py, c->k, dpsi);
    else
        wk->angle->skipped++;
}

/* Small steps are split in the statistics by whether they change the technique the chain had
 * before the iteration (wk->tech_before, before PITP's perturbation). */
void mutation_decide(struct worker *wk, struct chain *c, int kind, const struct proposal *pr, double t_start)
{
    double a = c->f > 0 ? mind(pr->f * pr->tr / c->f, 1.0) : 1.0;
    splat_ev_step(c->img, c, &wk->prop, pr->f, a, kind == PROPOSAL_LARGE);
    bool acc = rng_uniform(&wk->r) < a;
    if (wk->tech) tech_acc_step(wk->tech, a, acc, pr->f, c->f, c->scale);
    if (acc) {
        pss_accept(&c->pss);
        move_to(c->img, c, &wk->prop, pr->f);
        c->xsum_valid = false;
        if (wk->track) ctrl_path_capture(c->path, wk->spare->cam, pr->tech, wk->spare->emi, pr->k + 1 - pr->tech);
        if (wk->keep_path) {
            struct mmlt_path *t = c->x;
            c->x = wk->spare;
            wk->spare = t;
        }
    } else {
        pss_reject(&c->pss);
    }
    bool m = wk->multiplexed;
    int tech0 = wk->tech_before;
    stats_record_dt(wk->st, (enum proposal_kind)kind, m ? pr->k : 0, m && pr->tech != tech0,
                    m ? abs(pr->tech - tech0) : 0, pr->failed, a, acc, pr->f > 0, mutation_elapsed(wk, t_start));
    if (acc) {
        c->tech = pr->tech;
        c->k = pr->k;
    }
}

static bool is_large(const struct worker *wk, const struct chain *c, bool large)
{
    (void)wk, (void)c;
    return large;
}

static bool is_small(const struct worker *wk, const struct chain *c, bool large)
{
    (void)wk, (void)c;
    return !large;
}

static void large_step(struct worker *wk, struct chain *c, bool large, double t_start)
{
    struct proposal pr;
    mutation_propose(wk, c, large, &pr);
    /* fresh numbers: an independent sample of its length's b_k (progressive_norm.c) */
    target_sum_add(&wk->st->large[pr.k], pr.f);
    mutation_decide(wk, c, PROPOSAL_LARGE, &pr, t_start);
}

static void small_step(struct worker *wk, struct chain *c, bool large, double t_start)
{
    struct proposal pr;
    mutation_propose(wk, c, large, &pr);
    if (wk->opts->angle_stats) record_angle(wk, c, &pr);
    mutation_decide(wk, c, PROPOSAL_SMALL, &pr, t_start);
}

const struct mutation mutation_large = {.name = "large", .applies = is_large, .step = large_step};
const struct mutation mutation_small = {.name = "small", .applies = is_small, .step = small_step};
